// Tessellating a CadModel for a grid: loose faces sewn into shells (BRepBuilderAPI_Sewing), closed shells made
// solids (ShapeFix_Solid orients them outward), then every body meshed by BRepMesh_IncrementalMesh with a chordal
// deflection tied to the voxel size (docs/accuracy.md, "CAD tessellation").
//
// The mesher discretises every edge once and puts the same points into the triangulations of both faces that share
// it, so a solid's triangles meet at bit-identical vertices: a closed solid gives a watertight mesh by exact welding,
// which is what the voxelizer's auto mode checks. An assembly's instances share their part's triangulation; each is
// placed by its own location, computed in double before rounding to float.
#include <map>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "io/cad_model_impl.h"
#include "io/mesh_findings.h"
#include "io/occt_support.h"
#include "vox/core/grid_placement.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

struct CadBody {
  TopoDS_Shape shape;
  std::string name;
};

struct CadBodies {
  std::vector<CadBody> bodies;
  int64_t open_shells = 0, open_faces = 0, free_edges = 0;
  int64_t closed_by_sewing = 0;
};

std::string significantText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// "part.step: STEP (AUTOMOTIVE_DESIGN), unit 'INCH' (read as mm), 1 solid, 127 x 63.5 x 34.92 mm; tessellated
// within 0.0635 mm".
std::string summary(const CadModel::Impl& model, double deflection) {
  const glm::dvec3 e = model.bounds.extent();
  std::string s = model.name + ": " + model.format_detail + ", unit " +
                  (model.file_units.empty() ? std::string("not stated") : quoteBytes(model.file_units)) +
                  " (read as mm), " + countOf(model.solids, "solid");
  if (model.loose_faces > 0) s += " and " + countOf(model.loose_faces, "loose face");
  return s + ", " + significantText(e.x) + " x " + significantText(e.y) + " x " + significantText(e.z) +
         " mm; tessellated within " + significantText(deflection) + " mm";
}

// Sews the faces outside any solid (progress [0, 0.2]); closed shells become solids, open ones are kept apart.
Status sewLooseFaces(const TopoDS_Shape& shape, double tolerance, const std::string& name, const ProgressFn& progress,
                     CadBodies& out, std::vector<TopoDS_Shape>& open) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  int64_t faces = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE, TopAbs_SOLID); e.More(); e.Next(), ++faces) sewing.Add(e.Current());
  if (faces == 0) return Ok{};
  occt::ProgressBridge bridge(progress, 0.0, 0.2);
  sewing.Perform(bridge.Start());
  if (bridge.cancelled()) return makeError(ErrorCode::kCancelled, name + ": sewing cancelled");
  const TopoDS_Shape sewn = sewing.SewedShape();
  out.free_edges = sewing.NbFreeEdges();
  for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) {
    const TopoDS_Shell& shell = TopoDS::Shell(e.Current());
    if (BRep_Tool::IsClosed(shell)) {
      ShapeFix_Solid fix;
      out.bodies.push_back({fix.SolidFromShell(shell), "closed shell " + std::to_string(++out.closed_by_sewing)});
    } else {
      open.push_back(shell);
      ++out.open_shells;
      for (TopExp_Explorer f(shell, TopAbs_FACE); f.More(); f.Next()) ++out.open_faces;
    }
  }
  for (TopExp_Explorer e(sewn, TopAbs_FACE, TopAbs_SHELL); e.More(); e.Next()) {
    open.push_back(e.Current());
    ++out.open_faces;
  }
  return Ok{};
}

// The solids' names: their products' as the file names them ("bolt"; "bolt 1", "bolt 2" where a product is placed
// more than once), else "solid N" (N counting the solids from 1).
void nameBodies(const std::vector<std::string>& names, std::vector<CadBody>& bodies) {
  std::map<std::string, int> count, seen;
  for (size_t k = 0; k < bodies.size() && k < names.size(); ++k)
    if (!names[k].empty()) ++count[names[k]];
  for (size_t k = 0; k < bodies.size(); ++k) {
    const std::string& name = k < names.size() ? names[k] : std::string();
    if (name.empty()) {
      bodies[k].name = "solid " + std::to_string(k + 1);
    } else {
      bodies[k].name = count[name] > 1 ? name + " " + std::to_string(++seen[name]) : name;
    }
  }
}

// The bodies to mesh: the file's solids, then sewn shells; open surfaces only when nothing is closed.
Result<CadBodies> collectBodies(const CadModel::Impl& model, const TopoDS_Shape& shape, double tolerance,
                                const ProgressFn& progress, std::vector<std::string>& warnings) {
  CadBodies out;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) out.bodies.push_back({e.Current(), ""});
  nameBodies(model.solid_names, out.bodies);
  std::vector<TopoDS_Shape> open;
  if (Status s = sewLooseFaces(shape, tolerance, model.name, progress, out, open); !s.ok()) return s.error();
  if (open.empty()) return out;
  const std::string what = std::to_string(out.open_faces) + " faces that sewing (tolerance " +
                           significantText(tolerance) + " mm) leaves open, with " + std::to_string(out.free_edges) +
                           " free edges";
  if (!out.bodies.empty()) {
    warnings.push_back(model.name + ": left out " + what + " (outside the file's closed bodies)");
    return out;
  }
  warnings.push_back(model.name + ": open surface: " + what +
                     "; it has no inside of its own (voxelized as an open "
                     "mesh: auto mode votes)");
  int64_t k = 0;
  for (const TopoDS_Shape& s : open) out.bodies.push_back({s, "open surface " + std::to_string(++k)});
  return out;
}

// The triangles of one body's faces, outward facing, placed by each face's location. Returns the faces that have
// no triangulation (the mesher failed on them).
int64_t appendTriangles(const TopoDS_Shape& body, std::vector<Triangle>& triangles) {
  int64_t unmeshed = 0;
  for (TopExp_Explorer e(body, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
    if (mesh.IsNull()) {
      ++unmeshed;
      continue;
    }
    const gp_Trsf placement = location.Transformation();
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (Standard_Integer i = 1; i <= mesh->NbTriangles(); ++i) {
      Standard_Integer n[3];
      mesh->Triangle(i).Get(n[0], n[1], n[2]);
      if (reversed) std::swap(n[1], n[2]);
      Triangle t;
      for (int c = 0; c < 3; ++c) {
        const gp_Pnt p = mesh->Node(n[c]).Transformed(placement);
        t.v[c] = glm::vec3(float(p.X()), float(p.Y()), float(p.Z()));
      }
      // The mesher puts several nodes on a degenerated edge (a sphere's pole, a cone's apex), all at one point: a
      // triangle with two of them has no area and uses its third edge once in each direction, which would make that
      // edge non-manifold. Leaving it out changes no surface.
      if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[2] == t.v[0]) continue;
      triangles.push_back(t);
    }
  }
  return unmeshed;
}

// BRepMesh over all bodies at once (shared parts are meshed once), progress [0.2, 0.9].
Status meshBodies(const CadBodies& bodies, double deflection, const std::string& name, const ProgressFn& progress) {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  for (const CadBody& b : bodies.bodies) builder.Add(all, b.shape);
  IMeshTools_Parameters params;
  params.Deflection = deflection;
  params.Angle = 0.5;
  params.Relative = Standard_False;
  params.InParallel = Standard_True;
  occt::ProgressBridge bridge(progress, 0.2, 0.9);
  BRepMesh_IncrementalMesh mesher(all, params, bridge.Start());
  if (bridge.cancelled()) return makeError(ErrorCode::kCancelled, name + ": tessellation cancelled");
  return Ok{};
}

Result<MeshFileLoad> gather(const CadModel::Impl& model, const CadBodies& bodies, double deflection) {
  MeshFileLoad out;
  out.mesh.name = model.name;
  out.format = model.format;
  out.format_detail = model.format_detail;
  out.units = "mm";
  out.file_units = model.file_units;
  out.deflection = deflection;
  int64_t unmeshed = 0;
  for (const CadBody& b : bodies.bodies) {
    MeshBody body{b.name, out.mesh.triangles.size(), 0};
    unmeshed += appendTriangles(b.shape, out.mesh.triangles);
    body.triangle_count = out.mesh.triangles.size() - body.first_triangle;
    out.bodies.push_back(std::move(body));
  }
  if (out.mesh.triangles.empty()) {
    return makeError(ErrorCode::kParse, model.name + ": the tessellation gave no triangles");
  }
  if (unmeshed > 0) {
    out.warnings.push_back(model.name + ": " + std::to_string(unmeshed) +
                           " faces could not be tessellated and are missing from the mesh");
  }
  return out;
}

}  // namespace

Result<double> cadDeflectionFor(const Box3d& bounds, int64_t resolution, double voxel_size) {
  auto placement =
      voxel_size > 0.0 ? placeGridByVoxelSize(bounds, voxel_size) : placeGridByResolution(bounds, resolution);
  if (!placement) return placement.error();
  return kCadDeflectionVoxels * placement->frame.voxel_size;
}

Result<MeshFileLoad> tessellateCad(const CadModel& cad, double deflection, const ProgressFn& progress) {
  const CadModel::Impl& model = cad.impl();
  if (!(deflection > 0.0) || !std::isfinite(deflection)) {
    return makeError(ErrorCode::kInvalidArgument, model.name + ": the deflection must be a positive length");
  }
  occt::silenceMessages();
  try {
    // A private copy: the mesher stores triangulations in the shape's faces, which other copies share.
    const TopoDS_Shape shape = BRepBuilderAPI_Copy(model.shape, Standard_True, Standard_False).Shape();
    std::vector<std::string> warnings;
    auto bodies = collectBodies(model, shape, deflection, progress, warnings);
    if (!bodies) return bodies.error();
    if (Status s = meshBodies(*bodies, deflection, model.name, progress); !s.ok()) return s.error();
    auto out = gather(model, *bodies, deflection);
    if (!out) return out.error();
    if (progress && !progress(0.95)) return makeError(ErrorCode::kCancelled, model.name + ": tessellation cancelled");
    out->warnings.insert(out->warnings.begin(), warnings.begin(), warnings.end());
    out->warnings.insert(out->warnings.begin(), model.warnings.begin(), model.warnings.end());
    out->notes.insert(out->notes.begin(), model.notes.begin(), model.notes.end());
    out->notes.insert(out->notes.begin(), summary(model, deflection));
    if (bodies->closed_by_sewing > 0) {
      out->notes.push_back(model.name + ": " + std::to_string(bodies->closed_by_sewing) +
                           " closed shells sewn from loose faces (tolerance " + significantText(deflection) + " mm)");
    }
    out->topology = analyzeTopology(out->mesh);
    addTopologyFindings(model.name, out->topology, out->warnings, out->notes);
    if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, model.name + ": tessellation cancelled");
    return out;
  } catch (const Standard_Failure& f) {
    return makeError(ErrorCode::kParse, model.name + ": Open CASCADE could not tessellate it: " + occt::failureText(f));
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, model.name + ": not enough memory to tessellate it");
  } catch (const std::length_error&) {
    return makeError(ErrorCode::kLimit, model.name + ": the tessellation has more triangles than voxmod reads");
  }
}

}  // namespace vox::io
