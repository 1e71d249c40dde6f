#include "io/zip_package.h"

#include <expat.h>
#include <minizip/unzip.h>
#include <minizip/zip.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>

#include "vox/io/file_util.h"

namespace vox::io {
namespace {

// ---- minizip over memory ----

struct MemoryFile {
  std::span<const uint8_t> in;          // reading
  std::vector<uint8_t>* out = nullptr;  // writing
  uint64_t pos = 0;
  bool zeros_past_end = false;  // reads past the end give zeros (see readEntry)
  uint64_t size() const { return out ? out->size() : in.size(); }
};

voidpf ZCALLBACK memOpen(voidpf opaque, const void*, int) { return opaque; }

uLong ZCALLBACK memRead(voidpf, voidpf stream, void* buf, uLong size) {
  auto* f = static_cast<MemoryFile*>(stream);
  const uint64_t n = std::min<uint64_t>(size, f->pos < f->size() ? f->size() - f->pos : 0);
  const uint8_t* data = f->out ? f->out->data() : f->in.data();
  if (n > 0) std::memcpy(buf, data + f->pos, n);
  if (f->zeros_past_end && n < size) {
    std::memset(static_cast<uint8_t*>(buf) + n, 0, size - n);
    f->pos += size;
    return size;
  }
  f->pos += n;
  return uLong(n);
}

uLong ZCALLBACK memWrite(voidpf, voidpf stream, const void* buf, uLong size) {
  auto* f = static_cast<MemoryFile*>(stream);
  if (!f->out) return 0;
  if (f->pos + size > f->out->size()) f->out->resize(f->pos + size);
  std::memcpy(f->out->data() + f->pos, buf, size);
  f->pos += size;
  return size;
}

ZPOS64_T ZCALLBACK memTell(voidpf, voidpf stream) { return static_cast<MemoryFile*>(stream)->pos; }

long ZCALLBACK memSeek(voidpf, voidpf stream, ZPOS64_T offset, int origin) {
  auto* f = static_cast<MemoryFile*>(stream);
  const uint64_t base = origin == ZLIB_FILEFUNC_SEEK_SET ? 0 : origin == ZLIB_FILEFUNC_SEEK_CUR ? f->pos : f->size();
  if (base + offset > f->size() && !f->out) return -1;
  f->pos = base + offset;
  return 0;
}

int ZCALLBACK memClose(voidpf, voidpf) { return 0; }
int ZCALLBACK memError(voidpf, voidpf) { return 0; }

zlib_filefunc64_def memoryFunctions(MemoryFile& file) {
  zlib_filefunc64_def f{};
  f.zopen64_file = memOpen;
  f.zread_file = memRead;
  f.zwrite_file = memWrite;
  f.ztell64_file = memTell;
  f.zseek64_file = memSeek;
  f.zclose_file = memClose;
  f.zerror_file = memError;
  f.opaque = &file;
  return f;
}

using Entry = ZipEntry;

// The entry's unpacked size. minizip 1.1 as Debian 12 ships it compares the 32-bit size fields with
// (unsigned long)-1, which on LP64 is not 0xffffffff, so it never reads a ZIP64 extra field (APPNOTE 4.5.3) and
// reports such an entry's sizes as 0xffffffff: the size is taken from the extra field here. UINT64_MAX: unknown.
uint64_t unpackedSize(const unz_file_info64& info, std::span<const uint8_t> extra) {
  if (info.uncompressed_size != 0xffffffffu) return info.uncompressed_size;
  for (size_t at = 0; at + 4 <= extra.size();) {
    const unsigned id = extra[at] | unsigned(extra[at + 1]) << 8;
    const size_t size = extra[at + 2] | size_t(extra[at + 3]) << 8;
    if (id == 0x0001 && size >= 8 && at + 4 + 8 <= extra.size()) {
      uint64_t v = 0;
      for (int i = 0; i < 8; ++i) v |= uint64_t(extra[at + 4 + i]) << (8 * i);
      return v;
    }
    at += 4 + size;
  }
  return UINT64_MAX;
}

// The current entry, unpacked: exactly its size, checked against its CRC-32. Because minizip thinks a ZIP64 entry's
// compressed data runs on to 4 GiB, the memory file answers reads past its end with zeros while such an entry is
// read: the deflate stream ends where it ends, and the CRC catches an entry that is really cut short. A size the
// archive cannot hold (stored data longer than the archive, deflated data beyond deflate's 1032:1 at most) is
// refused before anything is allocated for it.
Status readEntry(unzFile zip, MemoryFile& file, const unz_file_info64& info, uint64_t size, Entry& e,
                 const std::string& name) {
  const auto damaged = [&](const char* what) {
    return makeError(ErrorCode::kParse, name + ": damaged zip archive (entry " + quoteBytes(e.name) + " " + what + ")");
  };
  const uint64_t archive = file.in.size();
  if (size == UINT64_MAX || (info.compression_method == 0 && size > archive) || size / 1032 > archive) {
    return damaged("claims a size its data cannot hold");
  }
  if (unzOpenCurrentFile(zip) != UNZ_OK) return damaged("cannot be opened");
  file.zeros_past_end = info.compressed_size == 0xffffffffu;
  uint64_t got = 0;
  uint8_t buf[65536];
  while (got < size) {
    const int n = unzReadCurrentFile(zip, buf, unsigned(std::min<uint64_t>(size - got, sizeof buf)));
    if (n <= 0) break;
    e.bytes.insert(e.bytes.end(), buf, buf + n);
    got += uint64_t(n);
  }
  file.zeros_past_end = false;
  unzCloseCurrentFile(zip);
  if (got != size) return damaged("is shorter than its size");
  uLong crc = crc32(0L, Z_NULL, 0);
  for (uint64_t at = 0; at < size; at += 1 << 30) {
    crc = crc32(crc, e.bytes.data() + at, uInt(std::min<uint64_t>(size - at, 1 << 30)));
  }
  if (crc != info.crc) return damaged("fails its CRC check");
  return Ok{};
}

}  // namespace

Result<std::vector<ZipEntry>> readZip(std::span<const uint8_t> bytes, const std::string& name, const std::string& what,
                                      uint64_t max_bytes) {
  MemoryFile file;
  file.in = bytes;
  zlib_filefunc64_def functions = memoryFunctions(file);
  unzFile zip = unzOpen2_64("3mf", &functions);
  if (zip == nullptr) return makeError(ErrorCode::kParse, name + ": not a " + what + ": it is not a zip archive");
  std::vector<Entry> entries;
  uint64_t total = 0;
  Status status = Ok{};
  for (int r = unzGoToFirstFile(zip); r == UNZ_OK && status.ok(); r = unzGoToNextFile(zip)) {
    char entry_name[1024];
    uint8_t extra[1024];
    unz_file_info64 info{};
    if (unzGetCurrentFileInfo64(zip, &info, entry_name, sizeof entry_name, extra, sizeof extra, nullptr, 0) != UNZ_OK) {
      status = makeError(ErrorCode::kParse, name + ": damaged zip archive (a directory entry cannot be read)");
      break;
    }
    Entry e{entry_name, {}};
    const uint64_t size = unpackedSize(info, {extra, std::min<size_t>(info.size_file_extra, sizeof extra)});
    if (size != UINT64_MAX && size > max_bytes - std::min(total, max_bytes)) {
      status = makeError(ErrorCode::kLimit,
                         name + ": the " + what + " unpacks to more than " + std::to_string(max_bytes >> 20) + " MiB");
      break;
    }
    total += size;
    status = readEntry(zip, file, info, size, e, name);
    entries.push_back(std::move(e));
  }
  unzClose(zip);
  if (!status.ok()) return status.error();
  return entries;
}

Result<std::vector<uint8_t>> writeZip(const std::vector<ZipEntry>& entries, const std::string& name, bool deflate) {
  std::vector<uint8_t> out;
  MemoryFile file;
  file.out = &out;
  zlib_filefunc64_def functions = memoryFunctions(file);
  zipFile zip = zipOpen2_64("zip", APPEND_STATUS_CREATE, nullptr, &functions);
  if (zip == nullptr) return makeError(ErrorCode::kIo, name + ": could not start the zip package");
  bool ok = true;
  for (const ZipEntry& e : entries) {
    zip_fileinfo info{};
    ok = ok && e.bytes.size() < 0xffffffffu &&
         zipOpenNewFileInZip64(zip, e.name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, deflate ? Z_DEFLATED : 0,
                               deflate ? Z_DEFAULT_COMPRESSION : 0, 0) == ZIP_OK &&
         (e.bytes.empty() || zipWriteInFileInZip(zip, e.bytes.data(), unsigned(e.bytes.size())) == ZIP_OK) &&
         zipCloseFileInZip(zip) == ZIP_OK;
  }
  ok = zipClose(zip, nullptr) == ZIP_OK && ok;
  if (!ok || out.size() >= 0xffffffffu) {
    return makeError(ErrorCode::kLimit, name + ": could not write the zip package (an entry or the zip over 4 GiB?)");
  }
  return out;
}

namespace {

// ---- expat: the first element with a given name, and its attributes ----

struct Search {
  explicit Search(const char* e) : element(e) {}
  const char* element;
  std::vector<std::pair<std::string, std::string>> attributes;  // of the match
  bool found = false;
  XML_Parser parser = nullptr;
  // Relationship parts hold several elements; `want` picks the one whose attribute `key` ends with `suffix`.
  const char* key = nullptr;
  const char* suffix = nullptr;
};

bool endsWith(const std::string& s, const char* suffix) {
  const size_t n = std::strlen(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

void XMLCALL onStart(void* data, const XML_Char* element, const XML_Char** attributes) {
  auto* s = static_cast<Search*>(data);
  // Without namespace processing an element may carry a prefix ("m:model"): compare the local name.
  const char* colon = std::strrchr(element, ':');
  if (std::strcmp(colon ? colon + 1 : element, s->element) != 0) return;
  std::vector<std::pair<std::string, std::string>> attrs;
  bool wanted = s->key == nullptr;
  for (int i = 0; attributes[i] != nullptr; i += 2) {
    attrs.emplace_back(attributes[i], attributes[i + 1]);
    if (s->key && std::strcmp(attributes[i], s->key) == 0 && endsWith(attributes[i + 1], s->suffix)) wanted = true;
  }
  if (!wanted) return;
  s->attributes = std::move(attrs);
  s->found = true;
  XML_StopParser(s->parser, XML_FALSE);
}

bool findElement(const std::vector<uint8_t>& xml, Search& search) {
  XML_Parser parser = XML_ParserCreate(nullptr);
  if (parser == nullptr) return false;
  search.parser = parser;
  XML_SetUserData(parser, &search);
  XML_SetStartElementHandler(parser, onStart);
  // Parsed in pieces: expat's length is an int, and a model part may exceed 2 GiB.
  const size_t piece = size_t(1) << 24;
  for (size_t at = 0; at < xml.size() && !search.found; at += piece) {
    const size_t n = std::min(piece, xml.size() - at);
    const bool last = at + n == xml.size();
    if (XML_Parse(parser, reinterpret_cast<const char*>(xml.data() + at), int(n), last) == XML_STATUS_ERROR) break;
  }
  XML_ParserFree(parser);
  return search.found;
}

std::string attribute(const Search& s, const char* key) {
  for (const auto& [k, v] : s.attributes) {
    if (k == key) return v;
  }
  return "";
}

const Entry* entryNamed(const std::vector<Entry>& entries, std::string path) {
  while (!path.empty() && path.front() == '/') path.erase(path.begin());
  for (const Entry& e : entries) {
    if (e.name == path) return &e;
  }
  return nullptr;
}

// The root model part: the target of the package relationship of type .../3dmodel (3MF Core, "3D Model part").
const Entry* modelPart(const std::vector<Entry>& entries) {
  if (const Entry* rels = entryNamed(entries, "_rels/.rels")) {
    Search s("Relationship");
    s.key = "Type";
    s.suffix = "/3dmodel";
    if (findElement(rels->bytes, s)) {
      if (const Entry* model = entryNamed(entries, attribute(s, "Target"))) return model;
    }
  }
  return entryNamed(entries, "3D/3dmodel.model");
}

}  // namespace

Result<ThreeMfPackage> read3mfPackage(std::span<const uint8_t> bytes, const std::string& name, uint64_t max_bytes) {
  auto entries = readZip(bytes, name, "3MF file", max_bytes);
  if (!entries) return entries.error();
  const Entry* model = modelPart(*entries);
  if (model == nullptr) {
    return makeError(ErrorCode::kParse, name + ": not a 3MF file: the zip holds no 3D model part (3D/3dmodel.model)");
  }
  ThreeMfPackage out;
  Search s("model");
  if (!findElement(model->bytes, s)) {
    return makeError(ErrorCode::kParse,
                     name + ": 3MF model part " + quoteBytes(model->name) + " is not XML with a <model> element");
  }
  out.unit = attribute(s, "unit");
  if (out.unit.empty()) out.unit = "millimeter";
  auto zip = writeZip(*entries, name, false);
  if (!zip) return makeError(zip.error().code, name + ": could not repack the 3MF package (an entry over 4 GiB?)");
  out.zip = std::move(zip).value();
  return out;
}

}  // namespace vox::io
