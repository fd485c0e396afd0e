#pragma once
/// @file vdb_file_check.hpp
/// @brief The layout of a .vdb file checked before OpenVDB reads it. OpenVDB's reader trusts the
/// lengths a file declares: fuzzing found a 9 kB file whose corrupt metadata-string length made it
/// fill a 1.7 GB string before failing. Every length and offset in the header, the file's and each
/// grid's metadata and the grid descriptors must fit in the file; the grids' trees (read by
/// OpenVDB, whose failures become InputError) are not parsed here.
#include <string>

namespace lucent::vdb {

/// Throws InputError naming the file and what is wrong: not a VDB (magic number), a format older
/// than OpenVDB 3 (file version 222) or written as a stream without grid offsets, a string, a
/// metadata value or a count longer than the bytes left, a grid whose offsets point outside the
/// file.
void checkVdbLayout(const std::string& path);

}  // namespace lucent::vdb
