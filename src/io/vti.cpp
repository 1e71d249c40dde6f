// VTK image data through VTK (libvtk9-dev): a vtkImageData holding the arrays, written by vtkXMLImageDataWriter into
// memory. Fields are handed to VTK without a copy (their float vectors become the arrays' storage for the duration
// of the write); the voxels are expanded to one byte each, layer by layer in parallel.
//
// VTK reports problems through a process-wide output window that prints to the terminal. Library code here never
// prints, so that window is replaced (once) by one that keeps the calling thread's last message, which becomes the
// error's text.
#include "vox/io/vti.h"

#include <mutex>
#include <string>

#include <oneapi/tbb/global_control.h>
#include <vtkCallbackCommand.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include "vox/core/parallel.h"

namespace vox::io {
namespace {

thread_local std::string vtk_last_error;

// VTK's messages, kept instead of printed.
class KeepingOutputWindow : public vtkOutputWindow {
 public:
  static KeepingOutputWindow* New() { return new KeepingOutputWindow; }
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override { vtk_last_error = text ? text : ""; }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
};

void silenceVtk() {
  static std::once_flag once;
  std::call_once(once, [] {
    vtkNew<KeepingOutputWindow> window;
    vtkOutputWindow::SetInstance(window);  // VTK keeps a reference
  });
}

// The last line of VTK's message (the first lines say where in VTK's source it was raised).
std::string vtkError() {
  std::string s = vtk_last_error;
  vtk_last_error.clear();
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  const size_t nl = s.find_last_of('\n');
  if (nl != std::string::npos) s = s.substr(nl + 1);
  return s.empty() ? "the writer failed" : s;
}

vtkNew<vtkUnsignedCharArray> voxelArray(const VoxelGrid& grid) {
  vtkNew<vtkUnsignedCharArray> a;
  a->SetName("voxels");
  a->SetNumberOfValues(vtkIdType(grid.dims().count()));
  uint8_t* out = a->GetPointer(0);
  const int64_t layer = int64_t(grid.nx()) * grid.ny();
  forLayers(grid.nz(), threadsFor(grid.dims().count() / 64), [&](int, int32_t z) {
    uint8_t* o = out + layer * z;
    if (!grid.layerAllocated(z)) {
      std::fill(o, o + layer, uint8_t(0));
      return;
    }
    for (int32_t y = 0; y < grid.ny(); ++y) {
      const uint64_t* row = grid.rowWords(y, z);
      for (int32_t x = 0; x < grid.nx(); ++x, ++o) {
        const int64_t xp = int64_t(x) + 1;
        *o = uint8_t((row[xp >> 6] >> (xp & 63)) & 1u);
      }
    }
  });
  return a;
}

vtkNew<vtkFloatArray> fieldArray(const NamedField& f) {
  vtkNew<vtkFloatArray> a;
  a->SetName(f.name.c_str());
  // save = 1: VTK uses the field's storage and never frees it; the field outlives the writer.
  a->SetArray(const_cast<float*>(f.field->values.data()), vtkIdType(f.field->values.size()), 1);
  return a;
}

void addContent(vtkImageData* image, const VolumeContent& content) {
  const Dims d = content.dims();
  const GridFrame& frame = content.frame();
  const double h = frame.voxel_size;
  const glm::dvec3 c = frame.voxelCentre(0, 0, 0);
  image->SetDimensions(d.nx, d.ny, d.nz);
  image->SetSpacing(h, h, h);
  image->SetOrigin(c.x, c.y, c.z);
  if (content.voxels) {
    image->GetPointData()->AddArray(voxelArray(*content.voxels));
    image->GetPointData()->SetActiveScalars("voxels");
  }
  for (const NamedField& f : content.fields) image->GetPointData()->AddArray(fieldArray(f));
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue(frame.units);
  image->GetFieldData()->AddArray(units);
}

// Passes the writer's progress on; the progress function's wish to stop is noted and honoured after the write.
struct ProgressRelay {
  const ProgressFn* progress = nullptr;
  bool cancelled = false;
  static void relay(vtkObject* caller, unsigned long, void* client, void*) {
    auto* self = static_cast<ProgressRelay*>(client);
    const double f = static_cast<vtkXMLImageDataWriter*>(caller)->GetProgress();
    if (*self->progress && !(*self->progress)(0.3 + 0.7 * f)) self->cancelled = true;
  }
};

}  // namespace

Result<std::vector<uint8_t>> encodeVti(const VolumeContent& content, const ProgressFn& progress) {
  if (const std::string why = volumeContentProblem(content, VolumeFormat::kVti); !why.empty()) {
    return makeError(ErrorCode::kInvalidArgument, why);
  }
  // VTK's parallel loops (its SMP tools, on TBB) stay on the calling thread, as OpenVDB's do in encodeVdb: the
  // window runs the export as a background job beside its own threads, and the thread sanitizer cannot follow TBB's
  // synchronisation between its workers (memory a VTK worker freed, reused by an OpenVDB export, reads as a race).
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  silenceVtk();
  vtkNew<vtkImageData> image;
  addContent(image, content);
  if (progress && !progress(0.3)) return makeError(ErrorCode::kCancelled, "cancelled");

  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes, not base64
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(1);  // fast; 0/1 voxels and smooth fields compress well at any level
  writer->SetHeaderTypeToUInt64();
  writer->SetByteOrderToLittleEndian();
  writer->WriteToOutputStringOn();
  ProgressRelay relay{&progress};
  vtkNew<vtkCallbackCommand> on_progress;
  on_progress->SetCallback(&ProgressRelay::relay);
  on_progress->SetClientData(&relay);
  writer->AddObserver(vtkCommand::ProgressEvent, on_progress);
  vtk_last_error.clear();
  if (writer->Write() == 0) return makeError(ErrorCode::kIo, "VTK: " + vtkError());
  if (relay.cancelled) return makeError(ErrorCode::kCancelled, "cancelled");
  const std::string out = writer->GetOutputString();
  return std::vector<uint8_t>(out.begin(), out.end());
}

}  // namespace vox::io
