#include "data_notes.h"

#include <iostream>

namespace msmesh::cli {

std::vector<std::string> data_notes(const std::string& input, const ReadNotes& read,
                                    const std::vector<std::string>& carried, const Mesh& out,
                                    const std::string& output) {
  std::vector<std::string> notes;
  for (const std::string& d : read.dropped) notes.push_back(input + ": " + d);
  for (const std::string& c : carried) notes.push_back(c);
  if (!output.empty())
    for (const std::string& u : unsupported_attributes(out, output)) notes.push_back(output + ": " + u);
  return notes;
}

void print_notes(const std::vector<std::string>& notes) {
  for (const std::string& n : notes) std::cout << "  note: " << n << "\n";
}

void add_notes(Json& j, const std::vector<std::string>& notes) {
  if (notes.empty()) return;
  std::string list = "[";
  for (std::size_t i = 0; i < notes.size(); ++i) list += (i ? "," : "") + Json::quote(notes[i]);
  j.raw("notes", list + "]");
}

}  // namespace msmesh::cli
