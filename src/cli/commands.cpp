#include "cli/commands.h"

#include <cstdio>

#include <CLI/CLI.hpp>

#include "cli/cmd_list.h"

namespace vox::cli {

// The explicit table: name, one-line summary, the function that adds its options (cmd_<name>.cpp).
const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"voxelize",
       "Voxelize a mesh or CAD file (STL, OBJ, PLY, 3MF, glTF, OFF, STEP, IGES) into a .vxm or .binvox file",
       addVoxelizeCommand},
      {"info", "Describe a mesh or voxel file (dims, voxel size, filled and surface voxels)", addInfoCommand},
      {"section", "Write the section normal to X, Y or Z at an index as a PNG", addSectionCommand},
      {"peel", "Remove skin layers (one, N, or all down to the core)", addPeelCommand},
      {"xray", "X-ray thickness map (min, max or total material per ray) as PNG and CSV", addXrayCommand},
      {"mass", "Volume, centroid, inertia tensor and bounding box", addMassCommand},
      {"thickness", "Wall thickness: exact distance, local thickness, thin walls and hot spots (NRRD, PNG)",
       addThicknessCommand},
      {"render", "Render the surface voxels as shaded points to a PNG (headless)", addRenderCommand},
      {"convert", "Convert between formats: voxel files, volumes (.nrrd .vti .vdb .vox), surface meshes",
       addConvertCommand},
      {"batch", "Convert many files, one output each, in parallel or over MPI ranks, with a report", addBatchCommand},
      {"boolean", "Union, intersection, difference or xor of two parts on one lattice", addBooleanCommand},
      {"bodies", "Split a mesh into its bodies (a voxel file into its components), voxelized on one lattice",
       addBodiesCommand},
      {"interfere", "Which parts or bodies share voxels, how many and where", addInterfereCommand},
      {"clearance", "The smallest gap between two parts that do not touch", addClearanceCommand},
      {"printcheck", "3D printing: overhangs, support volume, trapped cavities, the best build direction",
       addPrintCheckCommand},
      {"casting",
       "Casting solidification: when each voxel freezes, hot spots, feeders and whether the casting is sound",
       addCastingCommand},
      {"report", "One HTML page of what voxmod computes of a part: model, walls, hot spots, printing, pictures",
       addReportCommand},
  };
  return table;
}

const Command* findCommand(const std::string& name) {
  for (const Command& c : commands())
    if (name == c.name) return &c;
  return nullptr;
}

int runCommandLine(int argc, char** argv) {
  CLI::App app{
      "voxmod: voxel solid modeler. With no subcommand, or with a mesh or voxel file, it opens the "
      "modeler window; with a subcommand it works headless.",
      "voxmod"};
  app.set_version_flag("--version", "voxmod 0.1.0");
  app.require_subcommand(1);
  app.footer(
      "Run 'voxmod SUBCOMMAND --help' for a subcommand's options. Exit codes: 0 ok, 1 usage, "
      "2 input or output error, 3 no usable OpenGL (render).");
  CommandContext ctx;
  for (const Command& c : commands()) {
    CLI::App* sub = app.add_subcommand(c.name, c.summary);
    c.add(*sub, ctx);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 1;  // --help and --version exit 0; every parse error is a usage error (1)
  }
  return ctx.exit_code;
}

}  // namespace vox::cli
