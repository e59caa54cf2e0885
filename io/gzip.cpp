// gzip.h: zlib's inflate and deflate with a gzip wrapper (windowBits 15 + 16), whole buffers
// in memory.
#include "gzip.h"

#include <zlib.h>

#include <limits>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/memory.h"

namespace msmesh::io_detail {

bool looks_gzipped(std::string_view data) {
  return data.size() >= 2 && static_cast<unsigned char>(data[0]) == 0x1f && static_cast<unsigned char>(data[1]) == 0x8b;
}

std::string gunzip(std::string_view data, const std::string& path) {
  if (!looks_gzipped(data)) throw IoError(path + ": not gzip data (a .gz file must start with the bytes 1f 8b)");
  std::string out;
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 16) != Z_OK) throw IoError(path + ": cannot initialise zlib");
  struct End {
    z_stream* zs;
    ~End() { inflateEnd(zs); }
  } end{&zs};
  std::size_t in_pos = 0;
  const std::size_t chunk = std::size_t(1) << 20;
  double checked = 0;  // bytes of output whose memory was checked
  while (true) {
    const std::size_t in_left = data.size() - in_pos;
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + in_pos));
    zs.avail_in = static_cast<uInt>(std::min<std::size_t>(in_left, std::numeric_limits<uInt>::max()));
    const std::size_t before = out.size();
    if (static_cast<double>(before + chunk) > checked) {
      checked = 2.0 * static_cast<double>(before + chunk);
      // The content, then the parsed mesh: about four times the content in all.
      check_memory(4.0 * checked, path + ": inflating gzip data (more than " + std::to_string(before) + " bytes)");
    }
    out.resize(before + chunk);
    zs.next_out = reinterpret_cast<Bytef*>(out.data() + before);
    zs.avail_out = static_cast<uInt>(chunk);
    const uInt avail_in0 = zs.avail_in;
    const int rc = inflate(&zs, Z_NO_FLUSH);
    in_pos += avail_in0 - zs.avail_in;
    out.resize(before + (chunk - zs.avail_out));
    if (rc == Z_STREAM_END) {
      // Another member may follow (concatenated gzip files); trailing zero padding is allowed.
      std::string_view rest = data.substr(in_pos);
      if (rest.find_first_not_of('\0') == std::string_view::npos) break;
      if (!looks_gzipped(rest))
        throw IoError(path + ": corrupt gzip file (" + std::to_string(rest.size()) +
                      " bytes of garbage after the compressed data)");
      inflateReset(&zs);
      continue;
    }
    if (rc == Z_DATA_ERROR)
      throw IoError(path + ": corrupt gzip file (" + std::string(zs.msg ? zs.msg : "invalid compressed data") + ")");
    if (rc == Z_MEM_ERROR) throw IoError(path + ": out of memory while inflating gzip data");
    if (rc == Z_BUF_ERROR || (rc == Z_OK && in_pos == data.size() && zs.avail_out != 0))
      throw IoError(path + ": truncated gzip file (the compressed data ends before its end marker)");
    if (rc != Z_OK) throw IoError(path + ": corrupt gzip file (zlib error " + std::to_string(rc) + ")");
  }
  return out;
}

std::string gzip(std::string_view data, const std::string& path) {
  z_stream zs{};
  if (deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw IoError(path + ": cannot initialise zlib");
  struct End {
    z_stream* zs;
    ~End() { deflateEnd(zs); }
  } end{&zs};
  std::string out;
  out.resize(deflateBound(&zs, static_cast<uLong>(data.size())) + 64);
  std::size_t in_pos = 0, out_pos = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    const std::size_t in_left = data.size() - in_pos;
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data() + in_pos));
    zs.avail_in = static_cast<uInt>(std::min<std::size_t>(in_left, std::numeric_limits<uInt>::max()));
    if (out.size() - out_pos < 1024) out.resize(out.size() * 2 + 1024);
    zs.next_out = reinterpret_cast<Bytef*>(out.data() + out_pos);
    zs.avail_out = static_cast<uInt>(std::min<std::size_t>(out.size() - out_pos, std::numeric_limits<uInt>::max()));
    const uInt in0 = zs.avail_in, out0 = zs.avail_out;
    rc = deflate(&zs, zs.avail_in == in_left ? Z_FINISH : Z_NO_FLUSH);
    in_pos += in0 - zs.avail_in;
    out_pos += out0 - zs.avail_out;
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) throw IoError(path + ": gzip compression failed");
  }
  out.resize(out_pos);
  return out;
}

}  // namespace msmesh::io_detail
