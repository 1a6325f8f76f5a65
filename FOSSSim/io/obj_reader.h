#pragma once
// Reads Wavefront OBJ files as mass-spring meshes.

#include <string>
#include <string_view>
#include <vector>

#include "core/limits.h"
#include "io/scene_error.h"
#include "mesh/mesh.h"

namespace fosssim {

/// Reads an OBJ file as a mass-spring mesh (docs/scenes-3d.md, 'Mesh files').
///   v x y z [w]        a vertex (w, a homogeneous weight, must be 1 if present);
///                      "v x y z r g b" (vertex colours) is accepted and the colour ignored
///   f a b c ...        a face of 3 or more corners; "f a b" (2 corners) is one spring
///   l a b c ...        a polyline: springs between consecutive vertices
/// Corners may be written v, v/vt, v//vn or v/vt/vn, each index a non-zero integer (anything
/// else, such as "1/", "1/x" or "1/2/3/4", is an error); indices start at 1, and a negative index
/// counts back from the last vertex read so far. vt, vn, vp, o, g, s, usemtl, mtllib and
/// comments (#) are ignored. Anything else is an error naming file, line and problem: an
/// unknown statement, a malformed or non-finite number, an index of 0 or past the last
/// vertex, a corner repeated within a face, a face of one corner, a file without vertices
/// (thrown as SceneError).
Mesh read_obj_file(const std::string& path);

/// Reads OBJ text; `name` stands for the file in messages. A face of more than
/// `max_face_corners` corners is refused (it would become n (n - 1) / 2 springs; the limit is
/// Limits::max_face_corners, --max-face-corners).
Mesh read_obj_text(std::string_view text, const std::string& name,
                   std::int64_t max_face_corners = Limits{}.max_face_corners);

/// The 1-based line of each vertex, face (Mesh::faces) and segment (Mesh::segments) of an OBJ
/// text, for readers that check more than read_obj_text does.
struct ObjLines {
  std::vector<int> vertices;
  std::vector<int> faces;
  std::vector<int> segments;
};

/// As above; with `planar`, a vertex may also be "v x y" (z = 0), and `lines`, when not null,
/// receives where each element was written.
Mesh read_obj_text(std::string_view text, const std::string& name, std::int64_t max_face_corners,
                   bool planar, ObjLines* lines);

}  // namespace fosssim
