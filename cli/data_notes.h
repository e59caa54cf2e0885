// Notes of data a command could not keep (docs/robustness.md, "Attributes"): what reading the
// input dropped (ReadNotes::dropped), what carrying the attributes over to new faces invented
// (carry_attributes) and what the output's format cannot hold (unsupported_attributes). They
// print as "  note: ..." lines, even with --quiet, and as a "notes" list in --json output.
#pragma once
#include <string>
#include <vector>

#include "json.h"
#include "msmesh/io.h"

namespace msmesh::cli {

/// The notes of one run: `input`'s reading notes, `carried` (from carry_attributes), and what
/// `output` (a mesh path; empty: none written) cannot hold of `out`.
std::vector<std::string> data_notes(const std::string& input, const ReadNotes& read,
                                    const std::vector<std::string>& carried, const Mesh& out,
                                    const std::string& output);

/// Prints each note as "  note: ..." on standard output.
void print_notes(const std::vector<std::string>& notes);

/// Adds the notes to a JSON object as "notes" (a list of strings; nothing when empty).
void add_notes(Json& j, const std::vector<std::string>& notes);

}  // namespace msmesh::cli
