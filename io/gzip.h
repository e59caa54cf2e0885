// gzip compression of whole files in memory (internal to msmesh_io; zlib): read_mesh inflates
// `.obj.gz`, `.ply.gz`, ... before parsing, write_mesh deflates the formatted file.
#pragma once
#include <string>
#include <string_view>

namespace msmesh::io_detail {

/// True when `data` starts with the gzip magic bytes (1f 8b).
bool looks_gzipped(std::string_view data);

/// The inflated content of the gzip data `data` (several concatenated members are joined, as
/// gunzip does). Throws IoError naming `path` for data that is not gzip, corrupt (a bad
/// checksum) or truncated, and checks the memory the content needs (a "gzip bomb" stops with
/// a clear error instead of exhausting memory).
std::string gunzip(std::string_view data, const std::string& path);

/// `data` compressed as one gzip member (zlib level 6). Throws IoError naming `path` when zlib fails.
std::string gzip(std::string_view data, const std::string& path);

}  // namespace msmesh::io_detail
