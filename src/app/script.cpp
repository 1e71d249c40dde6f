#include "app/script.h"

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>

#include "app/actions.h"
#include "vox/io/file_util.h"

namespace vox::app {
namespace {

struct Signature {
  const char* name;
  int min_args;
  int max_args;  // -1: any (the command uses `rest`)
};

// The harness's own commands (script.h); every other command is an action of the table (actions.h).
constexpr std::array<Signature, 13> kHarnessCommands = {{
    {"echo", 0, -1},
    {"sweep", 1, 2},
    {"screenshot", 1, -1},
    {"state", 1, -1},
    {"wait", 1, 2},
    {"wait-file", 1, 2},
    {"hover", 1, 3},
    {"click", 3, 3},
    {"press", 1, -1},
    {"type", 2, -1},
    {"press-all", 0, 0},
    {"expect-error", 1, -1},
    {"exit", 0, 0},
}};

// The word counts a command takes: a harness command's, or an action's (none for a menu item's run, on|off for a
// toggle, its values for run_with).
std::optional<Signature> findSignature(const std::string& name) {
  for (const Signature& s : kHarnessCommands) {
    if (name == s.name) return s;
  }
  const Action* a = findAction(name);
  if (!a) return std::nullopt;
  if (a->checked) return Signature{a->name, 0, 1};
  if (!a->run_with) return Signature{a->name, 0, 0};
  return Signature{a->name, a->run ? 0 : a->min_values, a->max_values};
}

}  // namespace

Result<std::vector<ScriptCommand>> parseScript(const std::string& text, const std::string& name) {
  std::vector<ScriptCommand> commands;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    ScriptCommand c;
    c.line = number;
    if (!(words >> c.name)) continue;  // blank or comment
    for (std::string w; words >> w;) c.args.push_back(w);
    const size_t start = line.find(c.name) + c.name.size();
    const size_t first = line.find_first_not_of(" \t", start);
    if (first != std::string::npos) {
      const size_t last = line.find_last_not_of(" \t\r");
      c.rest = line.substr(first, last - first + 1);
    }
    const std::string where = name + ":" + std::to_string(number) + ": ";
    const std::optional<Signature> sig = findSignature(c.name);
    if (!sig) return makeError(ErrorCode::kParse, where + "unknown command '" + c.name + "'");
    const int n = int(c.args.size());
    if (n < sig->min_args || (sig->max_args >= 0 && n > sig->max_args)) {
      return makeError(ErrorCode::kParse, where + "'" + c.name + "' takes " + std::to_string(sig->min_args) +
                                              (sig->max_args == sig->min_args ? ""
                                               : sig->max_args < 0            ? " or more"
                                                                   : " to " + std::to_string(sig->max_args)) +
                                              " arguments, found " + std::to_string(n));
    }
    commands.push_back(std::move(c));
  }
  return commands;
}

bool isHarnessCommand(const std::string& name) {
  return std::any_of(kHarnessCommands.begin(), kHarnessCommands.end(),
                     [&](const Signature& s) { return name == s.name; });
}

Result<std::vector<ScriptCommand>> loadScript(const std::filesystem::path& path) {
  auto bytes = io::readFileBytes(path);
  if (!bytes) return bytes.error();
  return parseScript(std::string(bytes->begin(), bytes->end()), path.string());
}

}  // namespace vox::app
