#pragma once
// The scene element <elasticbody>: a planar elastic body (sheet, rod, ring, polygon or OBJ
// triangle mesh) with its material given once (docs/scene-format.md, 'Elastic bodies from one
// element').

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/force.h"
#include "core/scene.h"
#include "io/input_files.h"
#include "mesh/elastic_body.h"

namespace fosssim {

class SceneErrorList;
class XmlElement;

/// The element's name, "elasticbody".
inline constexpr std::string_view kElasticBodyElement = "elasticbody";

/// Forces made by <elasticbody> elements, by tag ("elasticbodycstforce"). The loader sums each
/// group right after the scene's own elements of that tag, so that a scene and the file
/// FOSSSim-generate writes for it sum the same forces in the same order.
using ForcesByTag = std::map<std::string, std::vector<std::unique_ptr<Force>>, std::less<>>;

/// Reads the root's <elasticbody> elements in document order: each appends its vertices as
/// particles (after every other particle), the edges of its springs or triangles as edges, and
/// makes its forces through the force registry, as if the scene held one element per force.
/// A body is refused before it is generated when it would take the scene past
/// files.limits().max_particles (or a polygon past max_polygon_corners). An OBJ file is found
/// relative to the directory of `file` and read through `files`. Each element's problem (a
/// SceneError naming the scene file, line, element and attribute, or the OBJ file and its line)
/// goes into `errors`, and reading goes on with the next element.
/// A body as an <elasticbody> element describes it.
struct ElasticBodyDescription {
  ElasticShape shape;
  ElasticParticles particles;  ///< vertex v is the body's particle v
  ElasticMaterial material;
  /// Of every particle (particleradius, default SceneModel::kDefaultParticleRadius) and every
  /// edge (edgeradius, default SceneModel::kDefaultEdgeRadius), for drawing and collisions.
  double radius = 0.0;
  double edge_radius = 0.0;
};

/// What read_elastic_body_text found.
struct ElasticBodyText {
  ElasticBodyDescription body;
  std::vector<std::string> warnings;
};

/// Reads one <elasticbody .../> given as text, as a scene file's would be read, its particles
/// numbered from 0 (FOSSSim-generate builds the element from its command line, so that both
/// check and build bodies alike). `name` stands for the text in messages; an OBJ file is found
/// relative to its folder. Throws SceneError.
ElasticBodyText read_elastic_body_text(std::string_view element, const std::string& name,
                                       InputFiles& files);

/// Reads the OBJ file at `path` (through `files`) as the triangles of an elastic body: "v x y"
/// or "v x y 0" vertices, triangle faces only, none of zero area, every vertex on one. Throws
/// SceneError naming the OBJ file and line, with " (<context>)" after the problem.
ElasticShape read_elastic_obj(const std::string& path, InputFiles& files,
                              const std::string& context);

ForcesByTag read_elastic_bodies(const XmlElement& root, Scene& scene,
                                const std::string& file, InputFiles& files, SceneErrorList& errors);

}  // namespace fosssim
