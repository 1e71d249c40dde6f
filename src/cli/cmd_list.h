#pragma once
// One function per subcommand (cmd_<name>.cpp); commands.cpp lists them in its table.
namespace CLI {
class App;
}
namespace vox::cli {
struct CommandContext;
void addVoxelizeCommand(CLI::App& sub, CommandContext& ctx);
void addInfoCommand(CLI::App& sub, CommandContext& ctx);
void addSectionCommand(CLI::App& sub, CommandContext& ctx);
void addPeelCommand(CLI::App& sub, CommandContext& ctx);
void addXrayCommand(CLI::App& sub, CommandContext& ctx);
void addMassCommand(CLI::App& sub, CommandContext& ctx);
void addThicknessCommand(CLI::App& sub, CommandContext& ctx);
void addRenderCommand(CLI::App& sub, CommandContext& ctx);
void addConvertCommand(CLI::App& sub, CommandContext& ctx);
void addBatchCommand(CLI::App& sub, CommandContext& ctx);
void addBooleanCommand(CLI::App& sub, CommandContext& ctx);
void addBodiesCommand(CLI::App& sub, CommandContext& ctx);
void addInterfereCommand(CLI::App& sub, CommandContext& ctx);
void addClearanceCommand(CLI::App& sub, CommandContext& ctx);
void addPrintCheckCommand(CLI::App& sub, CommandContext& ctx);
void addReportCommand(CLI::App& sub, CommandContext& ctx);
void addCastingCommand(CLI::App& sub, CommandContext& ctx);
}  // namespace vox::cli
