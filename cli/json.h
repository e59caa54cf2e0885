// The CLI's JSON writer: the report library's (msmesh/json_writer.h), for the --json outputs.
#pragma once
#include "msmesh/json_writer.h"

namespace msmesh::cli {
using msmesh::Json;
}  // namespace msmesh::cli
