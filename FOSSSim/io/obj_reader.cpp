#include "io/obj_reader.h"

#include <algorithm>
#include <array>

#include "io/text_lines.h"

namespace fosssim {

namespace {

constexpr std::array<std::string_view, 8> kIgnored = {"vt", "vn", "vp",     "o",
                                                      "g",  "s",  "usemtl", "mtllib"};

/// A face or polyline as written, resolved once every vertex is known.
struct PendingElement {
  bool polyline = false;
  std::vector<int> corners;  // 0-based
  int line = 0;
};

class ObjParser {
 public:
  ObjParser(const std::string& name, std::int64_t max_face_corners, bool planar = false,
            ObjLines* lines = nullptr)
      : name_(name), max_face_corners_(max_face_corners), planar_(planar), lines_(lines) {}

  Mesh parse(std::string_view text) {
    int line = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++line;
      std::string_view content = text.substr(start, end - start);
      if (const auto hash = content.find('#'); hash != std::string_view::npos)
        content = content.substr(0, hash);
      parse_line(split_line(content), line);
      start = end + 1;
    }
    if (mesh_.vertices.empty()) fail(0, "the file has no vertices (\"v x y z\" lines)");
    for (const PendingElement& element : pending_) add_element(element);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw SceneError(name_, line, "", problem);
  }

  void parse_line(const std::vector<std::string_view>& words, int line) {
    if (words.empty()) return;
    const std::string_view keyword = words[0];
    if (keyword == "v") {
      read_vertex(words, line);
    } else if (keyword == "f" || keyword == "l") {
      read_element(words, line, keyword == "l");
    } else if (std::find(kIgnored.begin(), kIgnored.end(), keyword) == kIgnored.end()) {
      fail(line,
           "unknown statement " + quote(keyword) +
               " (FOSSSim reads v, f and l, and ignores vt, vn, vp, o, g, s, usemtl and mtllib)");
    }
  }

  void read_vertex(const std::vector<std::string_view>& words, int line) {
    const std::size_t count = words.size() - 1;
    if (count != 3 && count != 4 && count != 6 && !(planar_ && count == 2)) {
      fail(line, "a vertex needs 3 coordinates (\"v x y z\"), found " + std::to_string(count) +
                     " numbers");
    }
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k < words.size(); ++k) {
      double value = 0.0;
      if (!parse_finite(words[k], value)) {
        fail(line, "vertex coordinate " + quote(words[k]) + " is not a finite number");
      }
      if (k <= 3) x[static_cast<int>(k) - 1] = value;
      if (count == 4 && k == 4 && value != 1.0) {
        fail(line, "a vertex weight w other than 1 is not supported, found " + quote(words[k]));
      }
    }
    mesh_.vertices.push_back(x);
    if (lines_) lines_->vertices.push_back(line);
  }

  void read_element(const std::vector<std::string_view>& words, int line, bool polyline) {
    PendingElement element{polyline, {}, line};
    const auto corners = static_cast<std::int64_t>(words.size() - 1);
    if (!polyline && corners > max_face_corners_) {
      fail(line, "a face of " + std::to_string(corners) + " corners (it would make " +
                     std::to_string(corners * (corners - 1) / 2) + " springs), " +
                     over_limit(max_face_corners_, "corners", "--max-face-corners"));
    }
    for (std::size_t k = 1; k < words.size(); ++k)
      element.corners.push_back(read_corner(words[k], line));
    const std::size_t needed = 2;
    if (element.corners.size() < needed) {
      fail(line, std::string(polyline ? "a polyline" : "a face") +
                     " needs at least 2 vertices, found " + std::to_string(element.corners.size()));
    }
    pending_.push_back(std::move(element));
  }

  /// The 0-based vertex of a corner "v", "v/vt", "v//vn" or "v/vt/vn"; a negative v counts
  /// back from the vertices read so far. Range checks wait until all vertices are known.
  int read_corner(std::string_view word, int line) {
    const std::string_view index_text = word.substr(0, word.find('/'));
    int index = 0;
    if (!parse_int(index_text, index))
      fail(line, "corner " + quote(word) + " does not start with an integer vertex index");
    if (index == 0) fail(line, "corner " + quote(word) + ": OBJ vertex indices start at 1");
    check_corner_references(word, line);
    if (index < 0) {
      const int resolved = mesh_.num_vertices() + index;
      if (resolved < 0) {
        fail(line, "corner " + quote(word) + " counts back past the first vertex (only " +
                       std::to_string(mesh_.num_vertices()) + " read so far)");
      }
      return resolved;
    }
    return index - 1;
  }

  /// Refuses a corner that is not v, v/vt, v//vn or v/vt/vn with integer vt and vn.
  void check_corner_references(std::string_view word, int line) const {
    const std::size_t first = word.find('/');
    if (first == std::string_view::npos) return;
    const std::string_view rest = word.substr(first + 1);
    const std::size_t second = rest.find('/');
    const std::string_view texture = rest.substr(0, second);
    const std::string_view normal =
        second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
    int index = 0;
    const bool texture_ok = texture.empty() ? second != std::string_view::npos
                                            : parse_int(texture, index) && index != 0;
    const bool normal_ok = second == std::string_view::npos ||
                           (!normal.empty() && parse_int(normal, index) && index != 0);
    if (!texture_ok || !normal_ok) {
      fail(line, "corner " + quote(word) +
                     " is not v, v/vt, v//vn or v/vt/vn with non-zero integer indices");
    }
  }

  void add_element(const PendingElement& element) {
    const int n = mesh_.num_vertices();
    for (int corner : element.corners) {
      if (corner >= n) {
        fail(element.line, "vertex index " + std::to_string(corner + 1) +
                               " is past the last vertex (the file has " + std::to_string(n) + ")");
      }
    }
    if (element.polyline) {
      for (std::size_t k = 0; k + 1 < element.corners.size(); ++k) {
        if (element.corners[k] == element.corners[k + 1]) {
          fail(element.line, "the polyline repeats vertex " +
                                 std::to_string(element.corners[k] + 1) +
                                 " in a row, a spring of zero length");
        }
        mesh_.segments.push_back({element.corners[k], element.corners[k + 1]});
        if (lines_) lines_->segments.push_back(element.line);
      }
      return;
    }
    std::vector<int> sorted = element.corners;
    std::sort(sorted.begin(), sorted.end());
    if (const auto repeat = std::adjacent_find(sorted.begin(), sorted.end());
        repeat != sorted.end()) {
      fail(element.line, "the face uses vertex " + std::to_string(*repeat + 1) + " twice");
    }
    if (element.corners.size() == 2) {
      mesh_.segments.push_back({element.corners[0], element.corners[1]});
      if (lines_) lines_->segments.push_back(element.line);
    } else {
      mesh_.faces.push_back(element.corners);
      if (lines_) lines_->faces.push_back(element.line);
    }
  }

  const std::string& name_;
  std::int64_t max_face_corners_;
  bool planar_;
  ObjLines* lines_;
  Mesh mesh_;
  std::vector<PendingElement> pending_;
};

}  // namespace

Mesh read_obj_text(std::string_view text, const std::string& name, std::int64_t max_face_corners) {
  return ObjParser(name, max_face_corners).parse(text);
}

Mesh read_obj_text(std::string_view text, const std::string& name, std::int64_t max_face_corners,
                   bool planar, ObjLines* lines) {
  return ObjParser(name, max_face_corners, planar, lines).parse(text);
}

Mesh read_obj_file(const std::string& path) {
  return parse_text_file(path, [](std::string_view text, const std::string& name) {
    return read_obj_text(text, name);
  });
}

}  // namespace fosssim
