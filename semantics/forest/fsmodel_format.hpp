#pragma once
// The .fsmodel file: a forest model in a compact binary form of our own,
// small enough to ship in the repository and quick to load at start-up.
//
//   header (32 bytes, little-endian)
//     8  magic "FSMODEL" + NUL
//     4  u32 format version (kFsmodelVersion)
//     8  u64 payload size, uncompressed
//     4  u32 CRC-32 of the uncompressed payload
//     8  u64 compressed size = the rest of the file
//   payload, zlib-deflated
//     descriptor name (u32 length + bytes), genome (u32 length + 211 '0'/'1')
//     u8 images the forest was trained on: 0 colour, 1 grey, 255 unknown (format 2 on;
//       format 1 files, which lack it, are read as unknown)
//     class table: u32 count, then per class i32 id, name, u8 r g b
//     forest settings: i32 trees, depth, split variables, min samples; u64 seed
//     forest: i32 width; u32 count + i32 class ids (the vote columns);
//       u32 count + i32 root per tree; u32 node count, then columns:
//       i16 per node: split variable, or -1 - leaf class for a leaf;
//       per split node, in node order: f32 thresholds, then u32 (low - node),
//       then u32 (high - node): children are always after their parent, and
//       small offsets compress well.
//
// Columns rather than records so that each compresses on its own terms; a
// 100-tree forest of the thesis genome takes a few bytes per node.
#include <filesystem>

#include "semantics/forest/forest_model.hpp"

namespace facadeslam::semantics {

inline constexpr int kFsmodelVersion = 2;

// Writes atomically. Only the bytes: the caller checks the model first.
void write_fsmodel(const std::filesystem::path& path, const ForestModel& model);

// Reads and decodes the file. A short, damaged or foreign file, another
// format version, a CRC mismatch or an inconsistent forest is an Error that
// names the file and what was expected. The class table is not compared
// with anything here (forest_model.hpp does that).
ForestModel read_fsmodel(const std::filesystem::path& path);

}  // namespace facadeslam::semantics
