#include "app/script.h"

#include <array>
#include <sstream>

#include "vox/io/file_util.h"

namespace vox::app {
namespace {

struct Signature {
  const char* name;
  int min_args;
  int max_args;  // -1: any (the command uses `rest`)
};

// Argument counts per command; the meaning of each is checked when it runs (see script.h).
constexpr std::array<Signature, 31> kSignatures = {{
    {"open", 1, -1},        {"voxelize", 1, 2},     {"section", 1, 2},
    {"sweep", 1, 2},        {"peel", 1, 1},         {"xray", 2, 2},
    {"panel", 1, 1},        {"view", 1, 2},         {"zoom", 1, 1},
    {"lit", 1, 1},          {"round", 1, 1},        {"disputed", 1, 1},
    {"cut", 1, 1},          {"undo", 0, 0},         {"redo", 0, 0},
    {"save", 1, -1},        {"export-view", 1, -1}, {"export-section", 1, -1},
    {"export-xray", 1, -1}, {"export-csv", 1, -1},  {"screenshot", 1, -1},
    {"state", 1, -1},       {"wait", 1, 2},         {"wait-file", 1, 2},
    {"quit", 0, 0},         {"lod", 1, 1},          {"expect-error", 1, -1},
    {"hover", 1, 3},        {"dialog", 1, 1},       {"measure", 1, 3},
    {"export-size", 2, 2},
}};

const Signature* findSignature(const std::string& name) {
  for (const Signature& s : kSignatures) {
    if (name == s.name) return &s;
  }
  return nullptr;
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
    if (c.name == "echo") {
      commands.push_back(std::move(c));
      continue;
    }
    const Signature* sig = findSignature(c.name);
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

Result<std::vector<ScriptCommand>> loadScript(const std::filesystem::path& path) {
  auto bytes = io::readFileBytes(path);
  if (!bytes) return bytes.error();
  return parseScript(std::string(bytes->begin(), bytes->end()), path.string());
}

}  // namespace vox::app
