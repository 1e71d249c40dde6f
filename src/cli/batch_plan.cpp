// voxmod batch: the inputs, their output names, and the journal that lets --resume check what is done
// (docs/conventions.md, "Batch").
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <set>

#include "cli/batch.h"
#include "vox/io/file_util.h"
#include "vox/io/mesh_export.h"
#include "vox/io/volume_export.h"

namespace vox::cli {

namespace fs = std::filesystem;

std::vector<std::string> batchFormats() {
  std::vector<std::string> formats = {"binvox", "vxm"};
  for (const std::string& ext : io::volumeExtensions()) formats.push_back(ext.substr(1));
  for (const char* ext : {"stl", "ply", "obj", "3mf"}) formats.push_back(ext);
  return formats;
}

std::string normalizeBatchFormat(const std::string& text) {
  std::string f = text.starts_with('.') ? text.substr(1) : text;
  for (char& c : f) c = char(std::tolower(static_cast<unsigned char>(c)));
  const auto formats = batchFormats();
  return std::find(formats.begin(), formats.end(), f) != formats.end() ? f : std::string();
}

std::string BatchSettings::key() const {
  const VoxelizeParams& p = mesh.params;
  // %.17g: the voxel size's every bit, so a key made from the same options is the same string.
  char size[32];
  std::snprintf(size, sizeof size, "%.17g", p.voxel_size);
  return "format=" + format + " res=" + std::to_string(p.resolution) + " voxel_size=" + size +
         " mode=" + mesh.mode_text + " units=" + mesh.units;
}

Result<std::vector<std::string>> readInputList(const fs::path& list) {
  auto bytes = io::readFileBytes(list);
  if (!bytes) return bytes.error();
  std::vector<std::string> inputs;
  std::string line;
  auto take = [&] {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (!line.empty() && line[0] != '#') inputs.push_back(line);
    line.clear();
  };
  for (uint8_t c : *bytes) {
    if (c == '\n')
      take();
    else
      line += char(c);
  }
  take();
  return inputs;
}

namespace {

// The deepest directory holding every input (absolute, lexically normal).
fs::path commonDirectory(const std::vector<fs::path>& inputs) {
  fs::path common = inputs.front().parent_path();
  for (const fs::path& p : inputs) {
    const fs::path dir = p.parent_path();
    fs::path shared;
    auto a = common.begin(), b = dir.begin();
    for (; a != common.end() && b != dir.end() && *a == *b; ++a, ++b) shared /= *a;
    common = shared;
  }
  return common;
}

// Gives every output name that more than one item shares to none of them: each keeps its input's extension.
void keepExtensionsWhereNamesCollide(std::vector<BatchItem>& items, const std::vector<fs::path>& relative_inputs,
                                     const std::string& format) {
  std::map<std::string, int> uses;
  for (const BatchItem& item : items) ++uses[item.relative];
  for (size_t i = 0; i < items.size(); ++i) {
    if (uses[items[i].relative] > 1) items[i].relative = relative_inputs[i].string() + "." + format;
  }
}

}  // namespace

std::vector<BatchItem> planBatch(const std::vector<std::string>& inputs, const fs::path& outdir,
                                 const std::string& format) {
  std::vector<BatchItem> items(inputs.size());
  if (inputs.empty()) return items;
  std::vector<fs::path> absolute(inputs.size()), relative(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) absolute[i] = fs::absolute(inputs[i]).lexically_normal();
  const fs::path common = commonDirectory(absolute);
  for (size_t i = 0; i < inputs.size(); ++i) {
    relative[i] = absolute[i].lexically_relative(common);
    items[i].index = i;
    items[i].input = inputs[i];
    items[i].relative = fs::path(relative[i]).replace_extension("." + format).string();
    std::error_code ec;
    const auto size = fs::file_size(inputs[i], ec);
    items[i].input_bytes = ec ? 0 : size;
  }
  keepExtensionsWhereNamesCollide(items, relative, format);
  std::map<std::string, size_t> first_use;
  const fs::path out_abs = fs::absolute(outdir).lexically_normal();
  for (BatchItem& item : items) {
    item.output = outdir / item.relative;
    const auto [it, fresh] = first_use.emplace(item.relative, item.index);
    if (!fresh) {
      item.problem = "writes the same output as input " + std::to_string(it->second + 1) + " (" +
                     items[it->second].input + "): given twice";
    } else if ((out_abs / item.relative).lexically_normal() == absolute[item.index]) {
      item.problem = item.output.string() + ": the output would replace its own input";
    }
  }
  return items;
}

fs::path journalPath(const fs::path& outdir) { return outdir / ".voxmod-batch.jsonl"; }

Journal readJournal(const fs::path& outdir) {
  std::ifstream f(journalPath(outdir), std::ios::binary);
  Journal journal;
  std::string line;
  while (std::getline(f, line)) {
    Json entry = Json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (!entry.is_object() || !entry.contains("output") || !entry["output"].is_string()) continue;  // torn line
    std::string output = entry["output"];
    journal[std::move(output)] = std::move(entry);
  }
  return journal;
}

std::optional<FileStamp> fileStamp(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return FileStamp{uint64_t(st.st_size), int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

namespace {

// Appends `text` with one write() to the end of `path`, then flushes it to the disk.
Status appendLine(const fs::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return makeError(ErrorCode::kIo, path.string() + ": cannot open: " + std::strerror(errno));
  ssize_t n;
  do {
    n = ::write(fd, text.data(), text.size());
  } while (n < 0 && errno == EINTR);
  const int write_errno = n < 0 ? errno : (size_t(n) < text.size() ? ENOSPC : 0);
  const int sync_errno = write_errno == 0 && ::fdatasync(fd) != 0 ? errno : 0;
  ::close(fd);
  if (write_errno != 0 || sync_errno != 0) {
    return makeError(ErrorCode::kIo,
                     path.string() + ": write failed: " + std::strerror(write_errno != 0 ? write_errno : sync_errno));
  }
  return Ok{};
}

Result<uint32_t> fileCrc32(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return makeError(ErrorCode::kIo, path.string() + ": cannot read it back");
  uLong crc = crc32(0L, Z_NULL, 0);
  std::vector<char> buffer(1 << 20);
  while (f) {
    f.read(buffer.data(), std::streamsize(buffer.size()));
    crc = crc32(crc, reinterpret_cast<const Bytef*>(buffer.data()), uInt(f.gcount()));
  }
  if (f.bad()) return makeError(ErrorCode::kIo, path.string() + ": read back failed");
  return uint32_t(crc);
}

}  // namespace

Result<Json> journalEntry(const BatchItem& item, const BatchSettings& settings, const FileStamp& input,
                          const Json& line) {
  const auto output = fileStamp(item.output.string());
  if (!output) return makeError(ErrorCode::kIo, item.output.string() + ": missing after it was written");
  auto crc = fileCrc32(item.output);
  if (!crc) return crc.error();
  Json e;
  e["output"] = item.relative;
  e["input"] = item.input;
  e["input_size"] = input.size;
  e["input_mtime_ns"] = input.mtime_ns;
  e["settings"] = settings.key();
  e["size"] = output->size;
  e["crc32"] = *crc;
  e["dims"] = line["dims"];
  e["filled"] = line["filled"];
  e["warnings"] = line["warnings"];
  return e;
}

std::optional<Json> checkDone(const BatchItem& item, const Journal& journal, const BatchSettings& settings) {
  const double t0 = nowSeconds();
  const auto entry = journal.find(item.relative);
  if (entry == journal.end()) return std::nullopt;
  const Json& e = entry->second;
  const auto input = fileStamp(item.input);
  const auto output = fileStamp(item.output.string());
  if (!input || !output || e.value("settings", "") != settings.key()) return std::nullopt;
  if (e.value("input_size", uint64_t(0)) != input->size || e.value("input_mtime_ns", int64_t(0)) != input->mtime_ns)
    return std::nullopt;
  if (e.value("size", uint64_t(0)) != output->size) return std::nullopt;
  auto crc = fileCrc32(item.output);
  if (!crc || e.value("crc32", uint64_t(0)) != *crc) return std::nullopt;
  Json line;
  line["input"] = item.input;
  line["status"] = "skipped";
  line["output"] = item.output.string();
  line["dims"] = e.value("dims", Json());
  line["filled"] = e.value("filled", Json());
  line["warnings"] = e.value("warnings", Json::array());
  line["seconds"] = nowSeconds() - t0;
  line["error"] = nullptr;
  return line;
}

Status appendJournal(const fs::path& outdir, const Json& entry) {
  return appendLine(journalPath(outdir), entry.dump() + "\n");
}

Status appendReportLine(const fs::path& report, const Json& line) { return appendLine(report, line.dump() + "\n"); }

Status compactJournal(const fs::path& outdir) {
  std::string text;
  for (const auto& [output, entry] : readJournal(outdir)) text += entry.dump() + "\n";
  return io::writeFileAtomic(journalPath(outdir), text);
}

void removeStaleTemporaries(const std::vector<BatchItem>& items) {
  // io::writeFileAtomic's temporary name: '.', the target's name cut to 150 characters, ".tmp-", a suffix. Each
  // output directory is listed once (a dataset may put thousands of outputs in one).
  std::map<fs::path, std::set<std::string>> names_by_dir;
  for (const BatchItem& item : items) {
    const fs::path dir = item.output.parent_path().empty() ? fs::path(".") : item.output.parent_path();
    names_by_dir[dir].insert(item.output.filename().string().substr(0, 150));
  }
  for (const auto& [dir, names] : names_by_dir) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      const size_t tmp = name.rfind(".tmp-");
      if (name.starts_with('.') && tmp != std::string::npos && names.contains(name.substr(1, tmp - 1))) {
        std::error_code ignored;
        fs::remove(it->path(), ignored);
      }
    }
  }
}

Status prepareOutdir(const fs::path& outdir) {
  std::error_code ec;
  fs::create_directories(outdir, ec);
  if (ec) return makeError(ErrorCode::kIo, outdir.string() + ": cannot create the output directory: " + ec.message());
  if (!fs::is_directory(outdir, ec))
    return makeError(ErrorCode::kIo, outdir.string() + ": not a directory (the output directory)");
  const fs::path probe = outdir / (".voxmod-batch-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) {
    return makeError(ErrorCode::kIo,
                     outdir.string() + ": cannot write in the output directory: " + std::strerror(errno));
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return Ok{};
}

bool isDiskFull(const std::string& message) {
  return message.find(std::strerror(ENOSPC)) != std::string::npos ||
         message.find(std::strerror(EDQUOT)) != std::string::npos;
}

}  // namespace vox::cli
