#pragma once
// A 3MF package (a zip, 3MF Core Specification 1.2, "Package") made ready for assimp, and its length unit; zips read
// and written in memory (the 3MF files voxmod writes, io/mesh_export.cpp; voxmod projects, io/project_file.cpp).
//
// assimp 5.2 opens 3MF entries through minizip's 32-bit calls, which report the sizes of entries written with ZIP64
// fields (streaming zip writers do so, e.g. ../shared/meshes/cad/pyramids.3mf) as 4 GiB: it then reads nothing and
// returns an empty scene. voxmod reads every entry with minizip's 64-bit calls and writes them into a plain zip in
// memory (stored, no ZIP64 fields) that assimp reads. assimp does not report the model's unit either; it is read
// here from the root model part's <model unit="..."> with expat (default millimeter, as the specification says).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vox/core/result.h"

namespace vox::io {

struct ThreeMfPackage {
  std::vector<uint8_t> zip;  // every entry, stored, in a zip assimp's minizip calls read
  std::string unit;          // "micron", "millimeter", "centimeter", "inch", "foot", "meter"
};

// Fails (kParse) on bytes that are not a zip, a zip without a 3D model part; (kLimit) when the entries unpack to
// more than `max_bytes`.
Result<ThreeMfPackage> read3mfPackage(std::span<const uint8_t> bytes, const std::string& name, uint64_t max_bytes);

struct ZipEntry {
  std::string name;  // its path in the package, e.g. "3D/3dmodel.model"
  std::vector<uint8_t> bytes;
};

// Every entry of a zip in memory, unpacked and checked against its CRC-32. `name` names the file and `what` its kind
// ("3MF file", "voxmod project") in messages. Fails (kParse) on bytes that are not a zip or a damaged entry, (kLimit)
// when the entries unpack to more than `max_bytes`.
Result<std::vector<ZipEntry>> readZip(std::span<const uint8_t> bytes, const std::string& name, const std::string& what,
                                      uint64_t max_bytes);

// A zip of `entries` in memory, in order: each deflated (zlib's default level) or, with `deflate` false, stored; no
// ZIP64 fields, so fails (kLimit) for an entry or a zip past 4 GiB. `name` names the file in messages.
Result<std::vector<uint8_t>> writeZip(const std::vector<ZipEntry>& entries, const std::string& name, bool deflate);

}  // namespace vox::io
