#include "vox/cli/cli.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace vox::cli {

namespace {

// Levenshtein distance, for "did you mean".
size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// A first argument that is neither a subcommand nor an option nor a file, and does not look like a path (no '.' or
// '/'): a mistyped subcommand, refused here rather than opened as a file by the window.
bool looksLikeAMistypedCommand(const std::string& first) {
  if (first.empty() || first[0] == '-' || first.find_first_of("./\\") != std::string::npos) return false;
  std::error_code ec;
  return !std::filesystem::exists(first, ec);
}

int unknownCommand(const std::string& first) {
  std::string best;
  size_t best_distance = 3;  // suggest only close names
  std::string names;
  for (const Command& c : commands()) {
    names += std::string(names.empty() ? "" : ", ") + c.name;
    const size_t d = editDistance(first, c.name);
    if (d < best_distance) best_distance = d, best = c.name;
  }
  std::fprintf(stderr, "voxmod: '%s' is neither a subcommand nor a file%s\nsubcommands: %s (voxmod --help)\n",
               first.c_str(), best.empty() ? "" : ("; did you mean '" + best + "'?").c_str(), names.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv, GuiEntry gui) {
  // A subcommand, --help or --version: headless. Anything else (no arguments, a file, the window's own options
  // such as --script) opens the GUI, which reports options it does not know.
  const std::string first = argc >= 2 ? argv[1] : "";
  const bool headless = findCommand(first) != nullptr || first == "--help" || first == "-h" || first == "--version";
  if (headless) return runCommandLine(argc, argv);
  if (looksLikeAMistypedCommand(first)) return unknownCommand(first);
  return gui(argc, argv);
}

}  // namespace vox::cli
