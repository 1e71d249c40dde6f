// The report: the analyses run once, then one HTML page. See vox/workflow/report.h.
#include "vox/workflow/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "vox/analysis/analysis.h"
#include "vox/analysis/printability.h"
#include "vox/analysis/walls.h"
#include "vox/core/units.h"
#include "vox/io/html.h"
#include "vox/io/image_io.h"
#include "vox/workflow/print_check.h"
#include "vox/workflow/thickness_figure.h"
#include "vox/workflow/thickness_run.h"

namespace vox::workflow {
namespace {

std::string num(double v, int digits = 4) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// The page being written: headings, tables of label and value, pictures.
class Page {
 public:
  explicit Page(std::string units) : units_(std::move(units)) {}
  std::string length(double v) const { return num(v) + " " + io::escapeHtml(unitsLabel(units_)); }
  std::string area(double v) const { return length(v) + "&sup2;"; }
  std::string volume(double v) const { return length(v) + "&sup3;"; }
  std::string point(glm::dvec3 p) const {
    return "(" + num(p.x, 5) + ", " + num(p.y, 5) + ", " + num(p.z, 5) + ") " + io::escapeHtml(unitsLabel(units_));
  }

  void heading(const std::string& title) { html_ += "<h2>" + io::escapeHtml(title) + "</h2>\n"; }
  void text(const std::string& escaped) { html_ += "<p>" + escaped + "</p>\n"; }
  // Rows of (label, value), the values already HTML.
  void facts(const std::vector<std::pair<std::string, std::string>>& rows) {
    html_ += "<table>\n";
    for (const auto& [label, value] : rows)
      html_ += "<tr><th>" + io::escapeHtml(label) + "</th><td>" + value + "</td></tr>\n";
    html_ += "</table>\n";
  }
  // A table with a header row; cells already HTML.
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
    html_ += "<table>\n<tr>";
    for (const std::string& h : header) html_ += "<th>" + io::escapeHtml(h) + "</th>";
    html_ += "</tr>\n";
    for (const auto& row : rows) {
      html_ += "<tr>";
      for (const std::string& cell : row) html_ += "<td>" + cell + "</td>";
      html_ += "</tr>\n";
    }
    html_ += "</table>\n";
  }
  void picture(const std::string& title, const std::vector<uint8_t>& png) {
    html_ += "<figure><img alt=\"" + io::escapeHtml(title) + "\" src=\"" + io::pngDataUri(png) + "\"><figcaption>" +
             io::escapeHtml(title) + "</figcaption></figure>\n";
  }
  const std::string& html() const { return html_; }

 private:
  std::string units_;
  std::string html_;
};

void modelSection(Page& page, const VoxelGrid& grid, const MassProperties& m, const ReportOptions& o) {
  const std::string& units = grid.frame().units;
  page.heading("Model");
  std::vector<std::pair<std::string, std::string>> rows = {
      {"Voxels", std::to_string(grid.nx()) + " &times; " + std::to_string(grid.ny()) + " &times; " +
                     std::to_string(grid.nz()) + ", " + page.length(grid.voxelSize()) + " each"},
      {"Filled", std::to_string(m.filled)},
      {"Volume", page.volume(m.volume) + " &plusmn; " + page.volume(m.volume_error_bound)},
      {"Box", page.point(m.bbox.min) + " to " + page.point(m.bbox.max)},
      {"Size", page.point(m.bbox.extent())},
      {"Centroid", page.point(m.centroid)},
  };
  const double metres = metresPerUnit(units);
  if (o.density_kg_m3 > 0.0 && metres > 0.0) {
    const double kg = m.volume * metres * metres * metres * o.density_kg_m3;
    rows.emplace_back("Mass", num(kg) + " kg (" + io::escapeHtml(o.material.empty() ? "density" : o.material) + ", " +
                                  num(o.density_kg_m3) + " kg/m&sup3;)");
  } else if (o.density_kg_m3 > 0.0) {
    rows.emplace_back("Mass", "not given: the model's length units are not known");
  }
  page.facts(rows);
}

void wallsSection(Page& page, const ThicknessRun& run, const Walls& walls, const ReportOptions& o) {
  const ThicknessStats& s = run.thickness.stats;
  page.heading("Walls");
  page.facts({{"Thinnest wall", page.length(walls.wall_min) + " (convex edges and corners are not walls)"},
              {"Local thickness", page.length(s.min) + " to " + page.length(s.max) + ", mean " + page.length(s.mean)},
              {"Deepest point", page.length(run.distance_max) + " from the surface"}});
  if (o.min_wall <= 0.0) return;
  if (walls.regions.empty()) {
    page.text("No wall is thinner than " + page.length(o.min_wall) + ".");
    return;
  }
  page.text(std::to_string(walls.regions.size()) + " wall" + (walls.regions.size() == 1 ? " is" : "s are") +
            " thinner than " + page.length(o.min_wall) +
            (walls.specks > 0
                 ? " (and " + std::to_string(walls.specks) + " specks under " + page.area(walls.min_area) + ")"
                 : std::string()) +
            ":");
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < walls.regions.size() && i < 50; ++i) {
    const ThinWallRegion& r = walls.regions[i];
    rows.push_back(
        {std::to_string(i + 1), page.length(r.min), page.area(r.area), page.point(r.bbox.min), page.point(r.bbox.max)});
  }
  page.table({"#", "Wall", "Surface", "From", "To"}, rows);
}

void hotSpotSection(Page& page, const std::vector<HotSpot>& spots) {
  page.heading("Hot spots");
  page.text(
      "The centres of the thickest regions, where a casting freezes last. The modulus is Chvorinov's V/A of "
      "the region each feeds; an isolated one is fed only through a thinner neck.");
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < spots.size() && i < 30; ++i) {
    const HotSpot& h = spots[i];
    rows.push_back({std::to_string(i + 1), page.point(h.centre), page.length(h.radius), page.length(h.modulus),
                    h.isolated ? "yes" : "no"});
  }
  page.table({"#", "Centre", "Inscribed radius", "Modulus", "Isolated"}, rows);
}

void printSection(Page& page, const PrintCheck& p) {
  page.heading("Printing upright (+z)");
  page.facts({{"Overhang past 45°", page.area(p.support.overhang_area)},
              {"Support", page.volume(p.support.support_volume)},
              {"Build height", page.length(p.support.height)},
              {"Trapped cavities", std::to_string(p.cavities.size()) +
                                       (p.cavities.empty() ? "" : ", " + page.volume(p.trapped_volume) + " in all")}});
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < p.cavities.size() && i < 30; ++i) {
    const TrappedCavity& c = p.cavities[i];
    rows.push_back({std::to_string(i + 1), page.volume(c.volume), page.point(c.centre),
                    c.drain ? page.length(c.drain->length) + " from " + page.point(c.drain->to) : "none straight"});
  }
  if (!rows.empty()) page.table({"#", "Volume", "Centre", "Shortest drain"}, rows);
}

// The parts of an assembly, with their volumes and boxes.
void partsTable(Page& page, const Assembly& parts) {
  const Lattice& lattice = parts.lattice();
  const double voxel = lattice.voxel_size * lattice.voxel_size * lattice.voxel_size;
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < parts.size(); ++i) {
    const LatticeGrid placed = parts.placedVoxels(i);
    const Box3i box = placed.box();
    rows.push_back({std::to_string(i + 1), io::escapeHtml(parts.part(i).name),
                    page.volume(double(placed.grid.filledCount()) * voxel), page.point(lattice.corner(box.min)),
                    page.point(lattice.corner(box.max))});
  }
  page.table({"#", "Part", "Volume", "From", "To"}, rows);
}

// The pairs of parts sharing voxels: interference, or contact where the overlap is at most `contact` thick.
void interferenceTable(Page& page, const Assembly& parts, const Interference& found, double contact,
                       ReportFacts& counts) {
  const Lattice& lattice = parts.lattice();
  const double voxel = lattice.voxel_size * lattice.voxel_size * lattice.voxel_size;
  std::vector<std::vector<std::string>> rows;
  for (const InterferencePair& pair : found.pairs) {
    const bool touch = isContact(pair, contact);
    ++(touch ? counts.contact_pairs : counts.interfering_pairs);
    if (rows.size() >= 50) continue;
    rows.push_back({io::escapeHtml(parts.part(size_t(pair.a)).name), io::escapeHtml(parts.part(size_t(pair.b)).name),
                    touch ? "contact" : "<b>interference</b>", page.volume(double(pair.voxels) * voxel),
                    page.length(pair.thickness), page.point(pair.centre)});
  }
  std::string summary = std::to_string(counts.interfering_pairs) + " pair" +
                        (counts.interfering_pairs == 1 ? "" : "s") + " of parts interfere";
  if (contact > 0.0) {
    summary +=
        "; " + std::to_string(counts.contact_pairs) + " only touch (overlapping " + page.length(contact) + " or less)";
  }
  page.text(summary + ". An overlap's thickness is that of the voxels the two parts share.");
  if (!rows.empty()) page.table({"Part", "Part", "", "Overlap", "Thickness", "Centre"}, rows);
  if (found.multiple_overlap_voxels > 0) {
    page.text(std::to_string(found.multiple_overlap_voxels) + " voxels lie inside three parts or more.");
  }
}

void clearanceText(Page& page, const Assembly& parts, const ReportOptions::PartClearance& c) {
  if (c.a >= parts.size() || c.b >= parts.size()) return;
  const std::string names = io::escapeHtml(parts.part(c.a).name) + " and " + io::escapeHtml(parts.part(c.b).name);
  const Clearance& k = c.clearance;
  if (k.touching) {
    page.text("Clearance between " + names + ": they touch.");
  } else if (k.found) {
    page.text("Clearance between " + names + ": a gap of " + page.length(k.gap) + ", between " +
              page.point(k.centre_a) + " and " + page.point(k.centre_b) + " (the closest voxels' centres, " +
              page.length(k.centre_distance) + " apart).");
  }
}

std::string pageHead(const std::string& name) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>voxmod report: " +
         io::escapeHtml(name) +
         "</title>\n<style>body{font-family:sans-serif;max-width:62em;margin:2em auto;padding:0 1em;color:#222}"
         "table{border-collapse:collapse;margin:.5em 0}th,td{border:1px solid #ccc;padding:.25em .6em;"
         "text-align:left;vertical-align:top}th{background:#f2f4f7}img{max-width:100%;border:1px solid #ccc}"
         "figure{margin:1em 0}figcaption{color:#555}</style></head>\n<body>\n<h1>" +
         io::escapeHtml(name) + "</h1>\n";
}

}  // namespace

Result<std::string> buildReport(const VoxelGrid& grid, const ReportOptions& options,
                                const std::vector<ReportPicture>& pictures, ReportFacts* facts,
                                const ProgressFn& progress) {
  const auto share = [&progress](double from, double to) {
    return ProgressFn([&progress, from, to](double f) { return !progress || progress(from + (to - from) * f); });
  };
  const MassProperties mass = computeMassProperties(grid);
  if (mass.filled == 0) return makeError(ErrorCode::kInvalidArgument, "report: the model has no voxels");
  ThicknessRunOptions run_options;
  run_options.walls = WallRidgeParams{};
  // the stages' shares of the bar, in the order they run: distance, hot spots, wall ridge, local thickness
  const auto stage_share = [&share](ThicknessStage stage) {
    switch (stage) {
      case ThicknessStage::kDistance:
        return share(0.0, 0.1);
      case ThicknessStage::kHotSpots:
        return share(0.1, 0.2);
      case ThicknessStage::kWalls:
        return share(0.2, 0.3);
      default:
        return share(0.3, 0.7);
    }
  };
  auto run = runThickness(grid, run_options, [&](ThicknessStage stage, double f) { return stage_share(stage)(f); });
  if (!run) return run.error();
  const double h = grid.voxelSize();
  auto walls = findWalls(*run->ridge, run->thickness.radius, WallParams{options.min_wall > 0.0 ? options.min_wall : h});
  if (!walls) return walls.error();
  PrintCheckOptions print_options;
  print_options.mesh = options.mesh;
  const auto print_share = [&share](PrintStage stage) {
    switch (stage) {
      case PrintStage::kSurface:
        return share(0.7, 0.75);
      case PrintStage::kSupport:
        return share(0.75, 0.85);
      default:
        return share(0.85, 0.95);  // (an assembly's interference: 0.95 to 0.99)
    }
  };
  auto print = runPrintCheck(grid, print_options, [&](PrintStage stage, double f) { return print_share(stage)(f); });
  if (!print) return print.error();
  const Assembly* parts = options.parts && options.parts->size() >= 2 ? options.parts : nullptr;
  Interference interference;
  if (parts) {
    const std::vector<LatticeGrid> placed = parts->placedParts();
    auto found = findInterference(placed, parts->lattice(), share(0.95, 0.99));
    if (!found) return found.error();
    interference = std::move(found).value();
  }
  // the section through the middle of the part, coloured by thickness: a whole number of pixels per voxel, at least
  // 480 pixels wide for a small part, one pixel per voxel for a large one
  SectionParams section;
  section.axis = Axis::kZ;
  section.index = (mass.bbox_min_ijk.z + mass.bbox_max_ijk.z) / 2;
  const int32_t scale = std::clamp(480 / std::max(grid.nx(), 1), 1, 8);
  auto figure = thicknessSectionFigure(run->thickness, nullptr, section, grid.frame().units, scale);
  if (!figure) return figure.error();
  auto section_png = io::encodePng(*figure, "section.png");
  if (!section_png) return section_png.error();

  Page page(grid.frame().units);
  for (const ReportPicture& p : pictures) page.picture(p.title, p.png);
  modelSection(page, grid, mass, options);
  wallsSection(page, *run, *walls, options);
  page.picture("Section z = " + std::to_string(section.index) + " through the middle, coloured by local thickness",
               *section_png);
  hotSpotSection(page, run->hot_spots);
  printSection(page, *print);
  ReportFacts counts;
  if (parts) {
    page.heading("Assembly: " + std::to_string(parts->size()) + " parts");
    partsTable(page, *parts);
    interferenceTable(page, *parts, interference, options.contact, counts);
    if (options.clearance) clearanceText(page, *parts, *options.clearance);
  }
  if (facts) {
    *facts = ReportFacts{mass.volume,
                         walls->wall_min,
                         run->thickness.stats.max,
                         print->support.support_volume,
                         options.min_wall > 0.0 ? int64_t(walls->regions.size()) : 0,
                         int64_t(run->hot_spots.size()),
                         int64_t(print->cavities.size()),
                         options.parts ? int64_t(options.parts->size()) : 0,
                         counts.interfering_pairs,
                         counts.contact_pairs};
  }
  if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, "report cancelled");
  return pageHead(options.name.empty() ? std::string("voxmod report") : options.name) + page.html() +
         "<p><small>Made by voxmod 0.1.0. Lengths in " + io::escapeHtml(unitsLabel(grid.frame().units)) +
         ".</small></p>\n</body></html>\n";
}

}  // namespace vox::workflow
