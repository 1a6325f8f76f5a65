// OBJ meshes: what is read, and every malformed line rejected with its number.

#include "io/obj_reader.h"

#include <gtest/gtest.h>

#include "support/scratch_folder.h"
#include "support/thrown.h"

namespace fosssim {
namespace {

TEST(ObjReader, ReadsVerticesFacesSegmentsAndPolylines) {
  const auto mesh = read_obj_text(R"(# a quad, a triangle, a spring and a polyline
mtllib cloth.mtl
o cloth
v 0 0 0
v 1 0 0
v 1 1 0   # comments may follow
v 0 1 0
v 2 0.5 0 1
vt 0 0
vn 0 0 1
s off
usemtl red
f 1/1/1 2/1/1 3//1 4
f -4 5 -3
f 1 5
l 1 3 5
)",
                                  "quad.obj");
  EXPECT_EQ(mesh.num_vertices(), 5);
  EXPECT_EQ(mesh.vertices[4], Eigen::Vector3d(2.0, 0.5, 0.0));
  EXPECT_EQ(mesh.faces, (std::vector<std::vector<int>>{{0, 1, 2, 3}, {1, 4, 2}}));
  EXPECT_EQ(mesh.segments, (std::vector<std::array<int, 2>>{{0, 4}, {0, 2}, {2, 4}}));
}

TEST(ObjReader, AcceptsFacesBeforeTheirVerticesAndVertexColours) {
  const auto mesh =
      read_obj_text("f 1 2 3\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\n", "late.obj");
  EXPECT_EQ(mesh.faces.size(), 1u);
}

struct MalformedObj {
  const char* text;
  int line;
  const char* problem;
};

TEST(ObjReader, RejectsMalformedLinesWithTheirNumbers) {
  const MalformedObj cases[] = {
      {"v 0 0 0\nv 1 0\n", 2, "a vertex needs 3 coordinates"},
      {"v 0 0 0\nv 1 zero 0\n", 2, "vertex coordinate \"zero\" is not a finite number"},
      {"v 0 0 nan\n", 1, "\"nan\" is not a finite number"},
      {"v 0 0 0\nv +-1 0 0\n", 2, "vertex coordinate \"+-1\" is not a finite number"},
      {"v 0 0 0 2\n", 1, "weight"},
      {"v 0 0 0\nv 1 0 0\n\nf 1 0\n", 4, "OBJ vertex indices start at 1"},
      {"v 0 0 0\nv 1 0 0\nf 1 2 3\n", 3, "vertex index 3 is past the last vertex (the file has 2)"},
      {"v 0 0 0\nf -2 1\n", 2, "counts back past the first vertex"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1\n", 4, "the face uses vertex 1 twice"},
      {"v 0 0 0\nf 1\n", 2, "a face needs at least 2 vertices, found 1"},
      {"v 0 0 0\nv 1 0 0\nl 1 1 2\n", 3, "repeats vertex 1"},
      {"v 0 0 0\nf a b c\n", 2, "does not start with an integer vertex index"},
      {"v 0 0 0\ncurv 0 1 1 2\n", 2, "unknown statement \"curv\""},
      {"# nothing\n", 0, "the file has no vertices"},
      {"v 0 0 0\nv 1 0 0\nl 1/ 2\n", 3,
       "corner \"1/\" is not v, v/vt, v//vn or v/vt/vn with non-zero integer indices"},
      {"v 0 0 0\nv 1 0 0\nl 1// 2\n", 3, "corner \"1//\" is not"},
      {"v 0 0 0\nv 1 0 0\nl 1/x 2\n", 3, "corner \"1/x\" is not"},
      {"v 0 0 0\nv 1 0 0\nl 1/2/3/4 2\n", 3, "corner \"1/2/3/4\" is not"},
      {"v 0 0 0\nv 1 0 0\nl 1/0 2\n", 3, "corner \"1/0\" is not"},
      {"v 0 0 0\nv 1 0 0\nl 1//2x 2\n", 3, "corner \"1//2x\" is not"},
  };
  for (const MalformedObj& c : cases) {
    const SceneError mesh_error = thrown_by<SceneError>([&] { read_obj_text(c.text, "bad.obj"); });
    EXPECT_EQ(mesh_error.line(), c.line) << c.text;
    EXPECT_NE(mesh_error.problem().find(c.problem), std::string::npos) << mesh_error.what();
    if (c.line > 0) {
      EXPECT_EQ(std::string(mesh_error.what())
                    .rfind("bad.obj:" + std::to_string(c.line) + ": error: ", 0),
                0u)
          << mesh_error.what();
    }
  }
}

TEST(ObjReader, TakesEveryCornerForm) {
  const auto mesh =
      read_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/1 3//1\nf 1/1/1 2/-1/2 -1\n", "forms.obj");
  EXPECT_EQ(mesh.faces.size(), 2u);
}

TEST(ObjReader, RefusesAFaceOfMoreCornersThanTheLimit) {
  std::string text;
  for (int k = 0; k < 5; ++k) text += "v " + std::to_string(k) + " 0 0\n";
  text += "f 1 2 3 4 5\n";
  EXPECT_EQ(read_obj_text(text, "five.obj", 5).faces.size(), 1u);
  const SceneError error = thrown_by<SceneError>([&] { read_obj_text(text, "five.obj", 4); });
  EXPECT_EQ(error.line(), 6);
  EXPECT_EQ(error.problem(),
            "a face of 5 corners (it would make 10 springs), more than the limit of 4 corners "
            "(raise it with --max-face-corners N)");
  // A polyline of many vertices makes one spring per segment: no limit.
  EXPECT_EQ(read_obj_text(text + "l 1 2 3 4 5\n", "five.obj", 5).segments.size(), 4u);
}

TEST(ObjReader, ReportsMissingFiles) {
  testing::ScratchFolder dir;
  const SceneError mesh_error = thrown_by<SceneError>([&] { read_obj_file((dir / "absent.obj")); });
  EXPECT_NE(std::string(mesh_error.what()).find("cannot open the file"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
