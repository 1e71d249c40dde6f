#pragma once
// The subcommand table. Each subcommand lives in its own file (cmd_<name>.cpp) and is listed explicitly in
// commands.cpp: no self-registration through static constructors.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace vox::cli {

// Filled in by a subcommand's callback after parsing.
struct CommandContext {
  int exit_code = 0;
};

struct Command {
  const char* name;
  const char* summary;
  // Adds options to `sub` (already named and described) and sets its callback, which stores the exit code.
  void (*add)(CLI::App& sub, CommandContext& ctx);
};

const std::vector<Command>& commands();
const Command* findCommand(const std::string& name);
int runCommandLine(int argc, char** argv);

}  // namespace vox::cli
