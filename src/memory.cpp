#include "msmesh/memory.h"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "msmesh/errors.h"

namespace msmesh {
namespace {

/// MSMESH_MEMORY_LIMIT in bytes, 0 when unset. A value that is not a size is an error, not
/// "no limit": a typo must not silently lift the limit.
std::uint64_t env_limit() {
  const char* s = std::getenv("MSMESH_MEMORY_LIMIT");
  if (!s) return 0;
  const std::string text = s;
  auto refuse = [&]() {
    throw InvalidInput("MSMESH_MEMORY_LIMIT = '" + text +
                       "' is not a memory size; valid: a number of bytes > 0, optionally followed by K, M or G "
                       "(e.g. 512M), or unset for no limit");
  };
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) refuse();
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || !std::isfinite(v) || !(v > 0)) refuse();
  double mult = 1;
  if (*end) {
    switch (std::toupper(static_cast<unsigned char>(*end))) {
      case 'K':
        mult = 1024.0;
        break;
      case 'M':
        mult = 1024.0 * 1024;
        break;
      case 'G':
        mult = 1024.0 * 1024 * 1024;
        break;
      default:
        refuse();
    }
    if (end[1] != '\0' && !((end[1] == 'B' || end[1] == 'b') && end[2] == '\0')) refuse();
  }
  const double bytes = v * mult;
  if (!(bytes >= 1) || bytes > 1.8e19) refuse();
  return static_cast<std::uint64_t>(bytes);
}

std::uint64_t system_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  unsigned long long kb = 0;
  std::string unit;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") return static_cast<std::uint64_t>(kb) * 1024;
  }
#if defined(_SC_AVPHYS_PAGES) && defined(_SC_PAGESIZE)
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
#endif
  return 0;
}

std::string human(double bytes) {
  char buf[64];
  if (bytes >= 1e9)
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / 1e9);
  else if (bytes >= 1e6)
    std::snprintf(buf, sizeof buf, "%.1f MB", bytes / 1e6);
  else
    std::snprintf(buf, sizeof buf, "%.0f kB", bytes / 1e3);
  return buf;
}

}  // namespace

std::uint64_t available_memory_bytes() {
  const std::uint64_t sys = system_available(), env = env_limit();
  if (env > 0 && (sys == 0 || env < sys)) return env;
  return sys;
}

void check_memory(double bytes, const std::string& what) {
  const std::uint64_t sys = system_available(), env = env_limit();
  const std::uint64_t avail = available_memory_bytes();
  if (avail == 0 || !(bytes > static_cast<double>(avail))) return;
  const bool from_env = env > 0 && (sys == 0 || env < sys);
  throw InvalidInput(
      what + ": needs about " + human(bytes) + " of memory, but only " + human(double(avail)) + " is available (" +
      (from_env ? std::string("limit set by MSMESH_MEMORY_LIMIT") : std::string("MemAvailable in /proc/meminfo")) +
      ")");
}

}  // namespace msmesh
