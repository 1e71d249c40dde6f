// Reading STEP and IGES with Open CASCADE's data exchange (STEPControl_Reader, IGESControl_Reader), then healing the
// shape with ShapeFix_Shape. The readers convert the file's length unit to millimetres (xstep.cascade.unit = MM);
// the unit the file declares is kept for the report, and a unit the caller gives instead (the file's is wrong, as in
// ../shared/meshes/cad/bearing.iges) rescales the shape. Assembly instances come out of TransferRoots already placed
// (each solid carries its instance's location), so every placed part is its own solid.
//
// Open CASCADE reads a truncated STEP file only as far as it goes and may keep what it parsed, so voxmod checks the
// end markers itself first: a STEP file must end with END-ISO-10303-21 (io/step_check.h, which also refuses an entity
// name defined twice before Open CASCADE's quadratic search for it), an IGES file with its Terminate record. A file
// whose load leaves errors in the reader's check list (a syntax error, a reference to an entity of the wrong type) is
// refused too: the transfer would keep what it could, and on a dangling reference Open CASCADE 7.6 crashes (found by
// tests/fuzz/fuzz_mesh_file.cpp). The real files of ../shared/meshes/cad load without one.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <Bnd_Box.hxx>
#include <HeaderSection_FileSchema.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <Standard_Failure.hxx>
#include <Interface_InterfaceModel.hxx>
#include <IFSelect_WorkLibrary.hxx>
#include <STEPControl_Reader.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Shape.hxx>
#include <StepData_StepModel.hxx>
#include <StepShape_OrientedEdge.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_WorkSession.hxx>
#include <gp_Trsf.hxx>

#include "io/cad_model_impl.h"
#include "io/occt_support.h"
#include "io/step_check.h"
#include "io/step_names.h"
#include "vox/core/text.h"
#include "vox/core/units.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// Metres per unit for the names STEP and IGES files use ("millimetre", "INCH", "MM", "FT"); 0 when unknown.
double metresPerFileUnit(const std::string& name) {
  const std::string n = lower(name);
  if (n == "mm" || n.find("milli") != n.npos) return 0.001;
  if (n == "cm" || n.find("centi") != n.npos) return 0.01;
  if (n == "in" || n == "inch" || n.find("inch") != n.npos) return 0.0254;
  if (n == "ft" || n.find("foot") != n.npos || n.find("feet") != n.npos) return 0.3048;
  if (n == "um" || n == "mic" || n.find("micro") != n.npos) return 1e-6;
  if (n == "mil") return 2.54e-5;
  if (n == "km" || n.find("kilo") != n.npos) return 1000.0;
  if (n == "m" || n == "metre" || n == "meter") return 1.0;
  return 0.0;
}

bool isBlank(uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\0' || c == 0x1a; }

// An IGES file ends with its Terminate record: 'T' in column 73 of the last line.
Status checkIgesComplete(std::span<const uint8_t> bytes, const std::string& name) {
  size_t end = bytes.size();
  while (end > 0 && isBlank(bytes[end - 1])) --end;
  size_t begin = end;
  while (begin > 0 && bytes[begin - 1] != '\n' && bytes[begin - 1] != '\r') --begin;
  if (end - begin >= 73 && bytes[begin + 72] == 'T') return Ok{};
  return makeError(ErrorCode::kParse,
                   name + ": IGES file truncated: its last line is not a Terminate record ('T' in column 73)");
}

Error readFailure(const std::string& name, const char* format, const occt::ReaderLock& lock) {
  std::string m = name + ": not a readable " + format + " file";
  const std::vector<std::string> said = lock.failures();
  if (!said.empty()) m += " (Open CASCADE: " + said.front() + ")";
  return makeError(ErrorCode::kParse, m);
}

// The errors the reader's load left in its check list, as one refusal naming the first; Ok when there are none.
Status checkLoad(const XSControl_Reader& reader, const std::string& name, const char* format) {
  Interface_CheckIterator checks = reader.WS()->ModelCheckList(Standard_True);
  int64_t fails = 0;
  std::string first;
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& check = checks.Value();
    if (check.IsNull() || check->NbFails() == 0) continue;
    if (first.empty() && check->CFail(1) != nullptr) first = check->CFail(1);
    fails += check->NbFails();
  }
  if (fails == 0) return Ok{};
  return makeError(ErrorCode::kParse, name + ": malformed " + format + " file: " + countOf(fails, "error") +
                                          " (Open CASCADE: " + quoteBytes(first, 160) + ")");
}

// The schema named in a STEP file's header: "AUTOMOTIVE_DESIGN", "CONFIG_CONTROL_DESIGN", "AP242_...".
std::string stepSchema(const STEPControl_Reader& reader) {
  const auto model = Handle(StepData_StepModel)::DownCast(reader.Model());
  if (model.IsNull()) return "";
  const auto schema =
      Handle(HeaderSection_FileSchema)::DownCast(model->HeaderEntity(STANDARD_TYPE(HeaderSection_FileSchema)));
  if (schema.IsNull() || schema->NbSchemaIdentifiers() < 1 || schema->SchemaIdentifiersValue(1).IsNull()) return "";
  std::string s = schema->SchemaIdentifiersValue(1)->ToCString();
  return s.substr(0, s.find_first_of(" {"));
}

std::string igesVersion(int flag) {
  static const char* const kNames[] = {"1.0", "ANSI Y14.26M-1981", "2.0", "3.0", "ANSI Y14.26M-1987",
                                       "4.0", "ANSI Y14.26M-1989", "5.0", "5.1", "5.2",
                                       "5.3"};
  if (flag >= 1 && flag <= 11) return std::string("IGES ") + kNames[flag - 1];
  return "IGES (version flag " + std::to_string(flag) + ")";
}

// Reads through the reader's own session; transfers every root (placed) with progress in [0.1, 0.7].
template <class Reader>
Status transfer(Reader& reader, const std::string& name, const char* format, const occt::ReaderLock& lock,
                const ProgressFn& progress, TopoDS_Shape& shape) {
  if (progress && !progress(0.1)) return makeError(ErrorCode::kCancelled, name + ": reading cancelled");
  occt::ProgressBridge bridge(progress, 0.1, 0.7);
  reader.TransferRoots(bridge.Start());
  if (bridge.cancelled()) return makeError(ErrorCode::kCancelled, name + ": reading cancelled");
  shape = reader.NbShapes() > 0 ? reader.OneShape() : TopoDS_Shape();
  if (shape.IsNull()) {
    Error e = readFailure(name, format, lock);
    e.message += ": no shape could be transferred";
    return e;
  }
  return Ok{};
}

// An oriented edge whose edge is an oriented edge again, round to itself: Open CASCADE follows the chain by recursion
// (StepShape_OrientedEdge::EdgeStart, from the checks its work session computes as it takes the model) and
// overflows the stack (found by tests/fuzz/fuzz_mesh_file.cpp). Refused with the entity's number; chains that end
// are left alone.
Status checkOrientedEdges(const Handle(StepData_StepModel) & model, const std::string& name) {
  if (model.IsNull()) return Ok{};
  const int n = model->NbEntities();
  for (int i = 1; i <= n; ++i) {
    Handle(StepShape_OrientedEdge) edge = Handle(StepShape_OrientedEdge)::DownCast(model->Value(i));
    for (int steps = 0; !edge.IsNull(); ++steps) {
      if (steps > n) {
        return makeError(ErrorCode::kParse, name + ": malformed STEP file: the oriented edge #" +
                                                std::to_string(model->IdentLabel(model->Value(i))) +
                                                " leads round to itself through its edge elements");
      }
      edge = Handle(StepShape_OrientedEdge)::DownCast(edge->EdgeElement());
    }
  }
  return Ok{};
}

// STEPControl_Reader::ReadStream in two steps, to look at the model before the work session takes it (and computes
// its checks): the file read into a model by the session's own library and protocol, then handed to the session as
// ReadStream hands it.
Status readStepModel(STEPControl_Reader& reader, std::istream& stream, const std::string& name,
                     const occt::ReaderLock& lock) {
  const Handle(XSControl_WorkSession)& session = reader.WS();
  Handle(Interface_InterfaceModel) model;
  int read = -1;
  try {
    read = session->WorkLibrary()->ReadStream(name.c_str(), stream, model, session->Protocol());
  } catch (const Standard_Failure& failure) {
    return makeError(ErrorCode::kParse,
                     name + ": not a readable STEP file (Open CASCADE: " + occt::failureText(failure) + ")");
  }
  if (read != 0 || model.IsNull()) return readFailure(name, "STEP", lock);
  if (Status s = checkOrientedEdges(Handle(StepData_StepModel)::DownCast(model), name); !s.ok()) return s;
  session->SetModel(model);
  session->SetLoadedFile(name.c_str());
  session->InitTransferReader(4);
  return Ok{};
}

Status readStep(std::span<const uint8_t> bytes, const std::string& name, const ProgressFn& progress,
                CadModel::Impl& out) {
  if (Status s = checkStep(bytes, name); !s.ok()) return s;
  occt::ReaderLock lock;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  STEPControl_Reader reader;
  std::istringstream stream(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  if (Status s = readStepModel(reader, stream, name, lock); !s.ok()) return s;
  if (Status s = checkLoad(reader, name, "STEP"); !s.ok()) return s;
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  if (lengths.Length() > 0) out.file_units = lengths.Value(1).ToCString();
  const std::string schema = stepSchema(reader);
  out.format_detail = schema.empty() ? "STEP" : "STEP (" + schema + ")";
  if (Status s = transfer(reader, name, "STEP", lock, progress, out.shape); !s.ok()) return s;
  out.named_solids = stepSolidNames(reader);
  return Ok{};
}

Status readIgesFile(const std::filesystem::path& path, const std::string& name, const ProgressFn& progress,
                    CadModel::Impl& out) {
  occt::ReaderLock lock;
  Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  IGESControl_Reader reader;
  reader.SetReadVisible(Standard_True);  // blanked entities are construction geometry
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return readFailure(name, "IGES", lock);
  if (Status s = checkLoad(reader, name, "IGES"); !s.ok()) return s;
  const Handle(IGESData_IGESModel) model = reader.IGESModel();
  if (!model.IsNull()) {
    const IGESData_GlobalSection& global = model->GlobalSection();
    if (!global.UnitName().IsNull()) out.file_units = global.UnitName()->ToCString();
    out.format_detail = igesVersion(global.IGESVersion());
  }
  return transfer(reader, name, "IGES", lock, progress, out.shape);
}

// OCCT's IGES reader takes a file name only: bytes in memory go through a private temporary file.
Status readIgesBytes(std::span<const uint8_t> bytes, const std::string& name, const ProgressFn& progress,
                     CadModel::Impl& out) {
  static std::atomic<uint64_t> counter{0};
  std::error_code ec;
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path(ec) /
      ("voxmod-iges-" + std::to_string(getpid()) + "-" + std::to_string(counter.fetch_add(1)) + ".igs");
  if (ec) return makeError(ErrorCode::kIo, name + ": no temporary directory to read IGES from memory");
  {
    std::ofstream f(tmp, std::ios::binary);
    f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!f) {
      std::filesystem::remove(tmp, ec);
      return makeError(ErrorCode::kIo, name + ": could not write a temporary copy to " + tmp.string());
    }
  }
  Status s = readIgesFile(tmp, name, progress, out);
  std::filesystem::remove(tmp, ec);
  return s;
}

// The name of each solid of `shape`, in the order TopExp_Explorer meets them (empty where none), from the solids
// named as transferred: a solid is known by its TShape (an assembly's instances share their part's), after the
// healing's replacements where `context` holds them.
std::vector<std::string> namesInOrder(const TopoDS_Shape& shape,
                                      const std::vector<std::pair<TopoDS_Shape, std::string>>& named,
                                      const Handle(ShapeBuild_ReShape) & context) {
  std::map<const TopoDS_TShape*, std::string> by_shape;
  for (const auto& [solid, name] : named) {
    const TopoDS_Shape now = context.IsNull() ? solid : context->Value(solid);
    by_shape.emplace(now.TShape().get(), name);
  }
  std::vector<std::string> out;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
    const auto it = by_shape.find(e.Current().TShape().get());
    out.push_back(it == by_shape.end() ? std::string() : it->second);
  }
  return out;
}

// The caller's unit instead of the file's: the shape, already in mm from the file's unit, is scaled by
// (caller's unit / file's unit).
Status applyUnitOverride(const std::string& units, const std::string& name, CadModel::Impl& out) {
  if (units.empty()) return Ok{};
  const double wanted = metresPerUnit(units);
  if (wanted <= 0.0) return makeError(ErrorCode::kInvalidArgument, name + ": unknown unit '" + units + "'");
  double declared = metresPerFileUnit(out.file_units);
  if (declared <= 0.0) {
    out.notes.push_back(name + ": the file's unit " + quoteBytes(out.file_units) +
                        " is not one voxmod knows; read as millimetres before applying " + units);
    declared = 0.001;
  }
  const double factor = wanted / declared;
  out.notes.push_back(name + ": coordinates taken as " + units + " (the file says " +
                      (out.file_units.empty() ? std::string("nothing") : quoteBytes(out.file_units)) + "): scaled by " +
                      std::to_string(factor) + " into millimetres");
  if (factor == 1.0) return Ok{};
  gp_Trsf scale;
  scale.SetScale(gp_Pnt(0, 0, 0), factor);
  BRepBuilderAPI_Transform transform(out.shape, scale, Standard_True);
  if (!transform.IsDone()) return makeError(ErrorCode::kParse, name + ": the shape could not be rescaled");
  // the names follow the solids: the copy's k-th solid is the original's k-th
  const std::vector<std::string> names = namesInOrder(out.shape, out.named_solids, nullptr);
  out.shape = transform.Shape();
  out.named_solids.clear();
  size_t k = 0;
  for (TopExp_Explorer e(out.shape, TopAbs_SOLID); e.More() && k < names.size(); e.Next(), ++k) {
    if (!names[k].empty()) out.named_solids.emplace_back(e.Current(), names[k]);
  }
  return Ok{};
}

// The name of each solid of the healed shape, from the solids the transfer named (healing may have replaced them).
void nameSolids(const ShapeFix_Shape& fix, CadModel::Impl& out) {
  if (!out.named_solids.empty()) out.solid_names = namesInOrder(out.shape, out.named_solids, fix.Context());
  out.named_solids.clear();  // the solids as transferred are no longer needed
}

// ShapeFix_Shape (progress [0.7, 0.95]), then counts and the tight bounding box.
Status healAndMeasure(const std::string& name, const ProgressFn& progress, CadModel::Impl& out) {
  occt::ProgressBridge bridge(progress, 0.7, 0.95);
  ShapeFix_Shape fix(out.shape);
  fix.Perform(bridge.Start());
  if (bridge.cancelled()) return makeError(ErrorCode::kCancelled, name + ": healing cancelled");
  out.shape = fix.Shape();
  nameSolids(fix, out);
  for (TopExp_Explorer e(out.shape, TopAbs_SOLID); e.More(); e.Next()) ++out.solids;
  for (TopExp_Explorer e(out.shape, TopAbs_FACE, TopAbs_SOLID); e.More(); e.Next()) ++out.loose_faces;
  if (out.solids == 0 && out.loose_faces == 0) {
    return makeError(ErrorCode::kParse, name + ": the file holds no solid and no surface (nothing to voxelize)");
  }
  Bnd_Box box;
  BRepBndLib::AddOptimal(out.shape, box, Standard_False, Standard_False);
  if (box.IsVoid()) return makeError(ErrorCode::kParse, name + ": the shape has no extent");
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  out.bounds.expand({x0, y0, z0});
  out.bounds.expand({x1, y1, z1});
  if (!std::isfinite(x0 + y0 + z0 + x1 + y1 + z1)) {
    return makeError(ErrorCode::kParse, name + ": the shape's bounding box is not finite");
  }
  if (progress && !progress(1.0)) return makeError(ErrorCode::kCancelled, name + ": reading cancelled");
  return Ok{};
}

Result<CadModel> readCad(std::span<const uint8_t> bytes, const std::filesystem::path* path, const std::string& name,
                         MeshFormat format, const CadReadOptions& options) {
  auto impl = std::make_shared<CadModel::Impl>();
  impl->name = name;
  impl->format = format;
  try {
    Status s = Ok{};
    if (format == MeshFormat::kStep) {
      s = readStep(bytes, name, options.progress, *impl);
    } else if (format == MeshFormat::kIges) {
      s = checkIgesComplete(bytes, name);
      if (s.ok()) {
        s = path ? readIgesFile(*path, name, options.progress, *impl)
                 : readIgesBytes(bytes, name, options.progress, *impl);
      }
    } else {
      return makeError(ErrorCode::kInvalidArgument, name + ": not a CAD format (STEP or IGES)");
    }
    if (s.ok()) s = applyUnitOverride(options.units, name, *impl);
    if (s.ok()) s = healAndMeasure(name, options.progress, *impl);
    if (!s.ok()) return s.error();
  } catch (const Standard_Failure& f) {
    return makeError(ErrorCode::kParse, name + ": Open CASCADE could not read it: " + occt::failureText(f));
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, name + ": not enough memory to read it");
  }
  return CadModel(std::move(impl));
}

}  // namespace

CadModel::CadModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
const Box3d& CadModel::bounds() const { return impl_->bounds; }
int64_t CadModel::solids() const { return impl_->solids; }
int64_t CadModel::looseFaces() const { return impl_->loose_faces; }
MeshFormat CadModel::format() const { return impl_->format; }
const std::string& CadModel::formatDetail() const { return impl_->format_detail; }
const std::string& CadModel::fileUnits() const { return impl_->file_units; }
const std::string& CadModel::name() const { return impl_->name; }
const std::vector<std::string>& CadModel::warnings() const { return impl_->warnings; }
const std::vector<std::string>& CadModel::notes() const { return impl_->notes; }
const CadModel::Impl& CadModel::impl() const { return *impl_; }

Result<CadModel> readCadFile(const std::filesystem::path& path, const CadReadOptions& options) {
  auto bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  MeshFormat format = meshFormatFromContent(*bytes);
  if (!isCadFormat(format)) format = meshFormatFromExtension(path);
  return readCad(*bytes, &path, path.string(), format, options);
}

Result<CadModel> readCadBytes(std::span<const uint8_t> bytes, const std::string& name, MeshFormat format,
                              const CadReadOptions& options) {
  return readCad(bytes, nullptr, name, format, options);
}

}  // namespace vox::io
