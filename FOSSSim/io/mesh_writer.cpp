#include "io/mesh_writer.h"

#include "core/text.h"
#include "io/output_file.h"

namespace fosssim {

namespace {

void write_vertex_line(std::ostream& out, const char* keyword, const Eigen::Vector3d& x) {
  out << keyword << to_text(x.x()) << ' ' << to_text(x.y()) << ' ' << to_text(x.z());
}

}  // namespace

void write_obj_file(const std::string& path, const Mesh& mesh) {
  write_output_file(path, [&mesh](std::ostream& out) {
    out << "# written by FOSSSim: " << mesh.num_vertices() << " vertices, " << mesh.faces.size()
        << " faces, " << mesh.segments.size() << " extra springs (l)\n";
    for (const auto& x : mesh.vertices) {
      write_vertex_line(out, "v ", x);
      out << '\n';
    }
    for (const auto& face : mesh.faces) {
      out << 'f';
      for (int corner : face) out << ' ' << corner + 1;
      out << '\n';
    }
    for (const auto& [a, b] : mesh.segments) out << "l " << a + 1 << ' ' << b + 1 << '\n';
  });
}

void write_medit_file(const std::string& path, const Mesh& mesh) {
  write_output_file(path, [&mesh](std::ostream& out) {
    out << "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" << mesh.num_vertices() << '\n';
    for (const auto& x : mesh.vertices) {
      write_vertex_line(out, "", x);
      out << " 0\n";
    }
    out << "\nTetrahedra\n" << mesh.tets.size() << '\n';
    for (const auto& tet : mesh.tets) {
      out << tet[0] + 1 << ' ' << tet[1] + 1 << ' ' << tet[2] + 1 << ' ' << tet[3] + 1 << " 0\n";
    }
    out << "\nEnd\n";
  });
}

}  // namespace fosssim
