#include "core/force_registry.h"

#include <array>

#include "core/forces/constant_force.h"
#include "core/forces/drag_damping_force.h"
#include "core/forces/elastic_body_bending_force.h"
#include "core/forces/elastic_body_cst_force.h"
#include "core/forces/elastic_body_spring_force.h"
#include "core/forces/gravitational_force.h"
#include "core/forces/rigid_body_gravity_force.h"
#include "core/forces/rigid_body_spring_force.h"
#include "core/forces/rigid_body_wind_force.h"
#include "core/forces/simple_gravity_force.h"
#include "core/forces/spring_force.h"
#include "core/forces/vortex_force.h"

namespace fosssim {

namespace {
constexpr std::array kForceKinds = {
    ForceKind{"springforce", &make_spring_force},
    ForceKind{"simplegravity", &make_simple_gravity_force},
    ForceKind{"gravitationalforce", &make_gravitational_force},
    ForceKind{"constantforce", &make_constant_force},
    ForceKind{"dragdamping", &make_drag_damping_force},
    ForceKind{"vortexforce", &make_vortex_force},
    ForceKind{"elasticbodyspringforce", &make_elastic_body_spring_force, 4},
    ForceKind{"elasticbodybendingforce", &make_elastic_body_bending_force, 4},
    ForceKind{"elasticbodycstforce", &make_elastic_body_cst_force, 4},
    ForceKind{"rigidbodygravityforce", &make_rigid_body_gravity_force, 3},
    ForceKind{"rigidbodyspringforce", &make_rigid_body_spring_force, 3},
    ForceKind{"rigidbodywindforce", &make_rigid_body_wind_force, 3},
};
}  // namespace

std::span<const ForceKind> force_kinds() { return kForceKinds; }

const ForceKind* find_force_kind(std::string_view tag) {
  for (const ForceKind& kind : kForceKinds) {
    if (kind.tag == tag) return &kind;
  }
  return nullptr;
}

}  // namespace fosssim
