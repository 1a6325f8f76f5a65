// MEDIT .mesh files: what is read, and every malformed entry rejected with its line.

#include "io/medit_reader.h"

#include <gtest/gtest.h>

#include "support/thrown.h"

namespace fosssim {
namespace {

constexpr const char* kTwoTets = R"(MeshVersionFormatted 1
# two tets sharing a face
Dimension
3
Vertices
5
0 0 0 1
1 0 0 1
0 1 0 1
0 0 1 1
1 1 1 2
Triangles 1
1 2 3 0
Tetrahedra 2
1 2 3 4 0
2 3 4 5 0
Corners 0
End
)";

TEST(MeditReader, ReadsVerticesAndTetsAndSkipsOtherSections) {
  const auto mesh = read_medit_text(kTwoTets, "two.mesh");
  EXPECT_EQ(mesh.num_vertices(), 5);
  EXPECT_EQ(mesh.vertices[4], Eigen::Vector3d(1.0, 1.0, 1.0));
  EXPECT_EQ(mesh.tets, (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
  EXPECT_TRUE(mesh.faces.empty());
}

struct MalformedMedit {
  std::string text;
  int line;
  const char* problem;
};

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

TEST(MeditReader, RejectsMalformedFilesWithLineNumbers) {
  const std::string good = kTwoTets;
  const MalformedMedit cases[] = {
      {replaced(good, "Dimension\n3", "Dimension\n2"), 4, "only 3D meshes are supported"},
      {replaced(good, "1 0 0 1\n", "1 zero 0 1\n"), 8,
       "coordinate y of vertex 2 must be a finite number, found \"zero\""},
      {replaced(good, "Vertices\n5", "Vertices\nfive"), 6,
       "the number of Vertices must be an integer"},
      {replaced(good, "Tetrahedra 2", "Tetrahedra -2"), 14, "must not be negative"},
      {replaced(good, "2 3 4 5 0", "2 3 4 6 0"), 16,
       "tetrahedron vertex 6 is out of range (vertices are numbered 1 to 5)"},
      {replaced(good, "2 3 4 5 0", "2 3 4 0 0"), 16, "tetrahedron vertex 0 is out of range"},
      {replaced(good, "2 3 4 5 0", "2 3 3 5 0"), 16, "repeats a vertex"},
      {replaced(good, "1 1 1 2\n", "0.5 0.5 0 2\n"), 16, "flat (zero volume)"},
      {replaced(good, "Corners 0", "Hexagons 0"), 17, "unknown keyword \"Hexagons\""},
      {replaced(good, "Vertices\n5", "Vertices\n4"), 11, "unexpected number \"1\""},
      {good.substr(0, good.find("2 3 4 5 0")), 15,
       "the file ends where vertex 1 of tetrahedron 2 should be"},
      {replaced(good, "Tetrahedra 2\n1 2 3 4 0\n2 3 4 5 0\n", ""), 0, "no Tetrahedra section"},
  };
  for (const MalformedMedit& c : cases) {
    const SceneError mesh_error =
        thrown_by<SceneError>([&] { read_medit_text(c.text, "bad.mesh"); });
    EXPECT_EQ(mesh_error.line(), c.line) << mesh_error.what();
    EXPECT_NE(mesh_error.problem().find(c.problem), std::string::npos) << mesh_error.what();
  }
}

}  // namespace
}  // namespace fosssim
