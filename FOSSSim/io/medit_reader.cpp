#include "io/medit_reader.h"

#include <algorithm>
#include <array>

#include "io/text_lines.h"

namespace fosssim {

namespace {

/// Sections we skip, with the numbers each of their records holds.
struct SkippedSection {
  std::string_view keyword;
  int record_size;
};
constexpr std::array<SkippedSection, 13> kSkipped = {{{"Edges", 3},
                                                      {"Triangles", 4},
                                                      {"Quadrilaterals", 5},
                                                      {"Hexahedra", 9},
                                                      {"Corners", 1},
                                                      {"Ridges", 1},
                                                      {"RequiredVertices", 1},
                                                      {"RequiredEdges", 1},
                                                      {"RequiredTriangles", 1},
                                                      {"Normals", 3},
                                                      {"NormalAtVertices", 2},
                                                      {"Tangents", 3},
                                                      {"TangentAtVertices", 2}}};

class MeditParser {
 public:
  MeditParser(std::string_view text, const std::string& name)
      : words_(split_words(text)), name_(name) {}

  Mesh parse() {
    while (next_ < words_.size()) {
      const Word keyword = words_[next_++];
      if (keyword.text == "End") break;
      if (keyword.text == "MeshVersionFormatted") {
        read_int("the format version after MeshVersionFormatted");
      } else if (keyword.text == "Dimension") {
        const int dim = read_int("the dimension after Dimension");
        if (dim != 3)
          fail(previous_line(), "only 3D meshes are supported (Dimension 3), found Dimension " +
                                    std::to_string(dim));
      } else if (keyword.text == "Vertices") {
        read_vertices();
      } else if (keyword.text == "Tetrahedra") {
        read_tets();
      } else if (const SkippedSection* section = find_skipped(keyword.text)) {
        skip_section(*section);
      } else if (double number = 0.0; parse_finite(keyword.text, number)) {
        fail(keyword.line, "unexpected number " + quote(keyword.text) +
                               " where a keyword should be (does a section hold more records "
                               "than its count says?)");
      } else {
        fail(keyword.line, "unknown keyword " + quote(keyword.text) +
                               " (expected MeshVersionFormatted, Dimension, Vertices, Tetrahedra, "
                               "another MEDIT section or End)");
      }
    }
    if (mesh_.vertices.empty()) fail(0, "the file has no Vertices section (or it is empty)");
    if (pending_tets_.empty()) fail(0, "the file has no Tetrahedra section (or it is empty)");
    for (const auto& [tet, line] : pending_tets_) add_tet(tet, line);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw SceneError(name_, line, "", problem);
  }

  int previous_line() const { return words_[next_ - 1].line; }

  static const SkippedSection* find_skipped(std::string_view keyword) {
    for (const SkippedSection& section : kSkipped) {
      if (section.keyword == keyword) return &section;
    }
    return nullptr;
  }

  const Word& take(const std::string& what) {
    if (next_ >= words_.size()) {
      fail(words_.empty() ? 0 : words_.back().line, "the file ends where " + what + " should be");
    }
    return words_[next_++];
  }

  int read_int(const std::string& what) {
    const Word& word = take(what);
    int value = 0;
    if (!parse_int(word.text, value))
      fail(word.line, what + " must be an integer, found " + quote(word.text));
    return value;
  }

  double read_number(const std::string& what) {
    const Word& word = take(what);
    double value = 0.0;
    if (!parse_finite(word.text, value))
      fail(word.line, what + " must be a finite number, found " + quote(word.text));
    return value;
  }

  /// The count that starts a section. It is only ever looped over, each record consuming words
  /// of the file, never used to size anything: a count the file cannot hold ends at the file's
  /// end with a message, whatever it declares.
  int read_count(std::string_view section) {
    const int count = read_int("the number of " + std::string(section));
    if (count < 0)
      fail(previous_line(), "the number of " + std::string(section) +
                                " must not be negative, found " + std::to_string(count));
    return count;
  }

  void read_vertices() {
    if (!mesh_.vertices.empty()) fail(previous_line(), "a second Vertices section");
    const int count = read_count("Vertices");
    for (int v = 1; v <= count; ++v) {
      const std::string what = "vertex " + std::to_string(v);
      Eigen::Vector3d x;
      for (int c = 0; c < 3; ++c)
        x[c] = read_number("coordinate " + std::string(1, "xyz"[c]) + " of " + what);
      read_int("the reference number of " + what);
      mesh_.vertices.push_back(x);
    }
  }

  void read_tets() {
    const int count = read_count("Tetrahedra");
    for (int t = 1; t <= count; ++t) {
      const std::string what = "tetrahedron " + std::to_string(t);
      std::array<int, 4> tet;
      const int line = next_ < words_.size() ? words_[next_].line : 0;
      for (int c = 0; c < 4; ++c)
        tet[c] = read_int("vertex " + std::to_string(c + 1) + " of " + what);
      read_int("the reference number of " + what);
      pending_tets_.emplace_back(tet, line);
    }
  }

  void skip_section(const SkippedSection& section) {
    const int count = read_count(section.keyword);
    for (long k = 0; k < static_cast<long>(count) * section.record_size; ++k) {
      read_number("an entry of " + std::string(section.keyword));
    }
  }

  void add_tet(std::array<int, 4> tet, int line) {
    const int n = mesh_.num_vertices();
    for (int& index : tet) {
      if (index < 1 || index > n) {
        fail(line, "tetrahedron vertex " + std::to_string(index) +
                       " is out of range (vertices are numbered 1 to " + std::to_string(n) + ")");
      }
      --index;
    }
    std::array<int, 4> sorted = tet;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      fail(line, "the tetrahedron repeats a vertex");
    }
    if (compute_tet_volume(mesh_, tet) == 0.0) fail(line, "the tetrahedron is flat (zero volume)");
    mesh_.tets.push_back(tet);
  }

  std::vector<Word> words_;
  std::size_t next_ = 0;
  const std::string& name_;
  Mesh mesh_;
  std::vector<std::pair<std::array<int, 4>, int>> pending_tets_;
};

}  // namespace

Mesh read_medit_text(std::string_view text, const std::string& name) {
  return MeditParser(text, name).parse();
}

Mesh read_medit_file(const std::string& path) { return parse_text_file(path, read_medit_text); }

}  // namespace fosssim
