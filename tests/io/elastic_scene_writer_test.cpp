// The plain scene FOSSSim-generate writes for an elastic body (io/elastic_scene_writer.h): read
// back, it is the model the <elasticbody> element makes, bit for bit, even where numbers and
// indices are large (100000 is written "100000", never "1e+05").

#include "io/elastic_scene_writer.h"

#include <gtest/gtest.h>

#include <string>

#include "core/force_evaluation.h"
#include "core/force_set.h"
#include "io/elastic_body_element.h"
#include "io/scene_loader.h"

namespace fosssim {
namespace {

/// The scene text FOSSSim-generate would write for `element`.
std::string written_text(const std::string& element) {
  InputFiles files;
  const ElasticBodyText read = read_elastic_body_text(element, "element", files);
  return elastic_scene_text({}, read.body.shape, read.body.particles, read.body.material);
}

TEST(ElasticSceneWriter, WritesIndicesAsIntegersEvenPast99999) {
  const std::string text =
      written_text(R"(<elasticbody shape="rod" segments="100001" stretch="3" m="1"/>)");
  EXPECT_NE(text.find(R"(<elasticbodyspringforce i1="99999" i2="100000" )"), std::string::npos);
  EXPECT_NE(text.find(R"(<elasticbodyspringforce i1="100000" i2="100001" )"), std::string::npos);
  EXPECT_EQ(text.find(R"(="1e+05")"), std::string::npos);
}

TEST(ElasticSceneWriter, ReadsBackAsTheElementsModelBitForBit) {
  const std::string element =
      R"(<elasticbody shape="ring" segments="40" radius="1e5" stretch="3" bend="0.25" )"
      R"(totalmass="7" rotation="21" x="1e5" vy="-2" fixed="0 7"/>)";
  const Scene written = load_scene_text(written_text(element), "written.xml");
  const Scene direct = load_scene_text(
      "<scene>\n<duration time=\"5\"/>\n<integrator type=\"implicit-euler\" dt=\"0.01\"/>\n" +
          element + "\n</scene>\n",
      "direct.xml");
  ASSERT_EQ(written.model.num_particles(), 40);
  EXPECT_EQ(written.initial.q, direct.initial.q);
  EXPECT_EQ(written.initial.v, direct.initial.v);
  EXPECT_EQ(written.model.mass, direct.model.mass);
  EXPECT_EQ(written.model.fixed, direct.model.fixed);
  EXPECT_EQ(written.model.edges.size(), direct.model.edges.size());
  ASSERT_EQ(written.model.forces.size(), direct.model.forces.size());
  // The same forces in the same order: the same gradient, to the bit, away from rest.
  Vector q = direct.initial.q;
  for (int k = 0; k < q.size(); ++k) q[k] += 1e2 * ((k * 7919) % 13 - 6);
  const ForceSet a(written.model), b(direct.model);
  const Vector ga = compute_gradient(a, q, direct.initial.v);
  EXPECT_GT(ga.norm(), 0.0);
  EXPECT_EQ(ga, compute_gradient(b, q, direct.initial.v));
}

}  // namespace
}  // namespace fosssim
