#include "io/rigid_trajectory.h"

#include <bit>
#include <cstring>

#include "core/error.h"
#include "core/force_evaluation.h"
#include "core/rigid/rigid_bodies.h"

namespace fosssim {

std::int64_t rigid_trajectory_bytes(int bodies, std::int64_t steps) {
  const std::int64_t b = bodies;
  return 8 * (4 * b + (steps + 1) * (12 * b + 1));
}

Vector rigid_state_block(const SceneModel& model, const State& state) {
  const RigidBodies& bodies = *model.rigid_bodies;
  Vector block(6 * bodies.size());
  for (int b = 0; b < bodies.size(); ++b) {
    const Vec2 V = reported_velocity(bodies, state.v, b);
    block.segment<6>(6 * b) << state.q[3 * b], state.q[3 * b + 1], state.q[3 * b + 2], V.x(), V.y(),
        reported_omega(bodies, state.v, b);
  }
  return block;
}

Vector rigid_start_block(const SceneModel& model) {
  const RigidBodies& bodies = *model.rigid_bodies;
  const int n = bodies.size();
  Vector block(4 * n);
  for (int b = 0; b < n; ++b) {
    const RigidBody& body = bodies.bodies[b];
    block[b] = body.mass;
    block[n + 2 * b] = body.initial_center.x();
    block[n + 2 * b + 1] = body.initial_center.y();
    block[3 * n + b] = body.inertia;
  }
  return block;
}

Vector rigid_quantities_block(const ForceSet& forces, const Vector& q, const Vector& v) {
  const RigidBodies& bodies = *forces.model().rigid_bodies;
  const int n = bodies.size();
  Vector block(6 * n + 1);
  for (int b = 0; b < n; ++b) {
    const BodyQuantities body = compute_body_quantities(bodies, q, v, b);
    block[2 * b] = body.momentum.x();
    block[2 * b + 1] = body.momentum.y();
    block[2 * n + b] = body.orbital_angular_momentum;
    block[3 * n + b] = body.spin_angular_momentum;
    block[4 * n + b] = body.orbital_kinetic_energy;
    block[5 * n + b] = body.spin_kinetic_energy;
  }
  block[6 * n] = compute_potential_energy(forces, q, v);
  return block;
}

RigidTrajectoryWriter::RigidTrajectoryWriter(TrajectoryWriter writer, const SceneModel& model)
    : writer_(std::move(writer)), model_(&model), forces_(model) {}

void RigidTrajectoryWriter::write(const State& state) {
  writer_.write_values(rigid_state_block(*model_, state));
  if (!wrote_first_) {
    writer_.write_values(rigid_start_block(*model_));
    wrote_first_ = true;
  }
  writer_.write_values(rigid_quantities_block(forces_, state.q, state.v));
}

RigidTrajectoryReader RigidTrajectoryReader::open(const std::string& path, int bodies,
                                                  std::int64_t steps) {
  RegularFile file;
  try {
    file = open_regular_file(path);
  } catch (const Error& error) {
    throw Error(ErrorKind::kBadInput, error.what());
  }
  const std::int64_t expected = rigid_trajectory_bytes(bodies, steps);
  if (file.size != expected) {
    throw Error(ErrorKind::kBadInput,
                path + " holds " + std::to_string(file.size) + " bytes, but a rigid-body " +
                    "trajectory of " + std::to_string(bodies) + " bodies and " +
                    std::to_string(steps) + " steps holds exactly " + std::to_string(expected) +
                    " (8 (4B + (K + 1)(12B + 1)))" +
                    (file.size < expected ? ": the file was cut short" : ""));
  }
  return RigidTrajectoryReader(path, std::move(file), bodies);
}

void RigidTrajectoryReader::read_doubles(std::int64_t offset_doubles, Vector& out) {
  std::FILE* file = file_.stream.get();
  const auto count = static_cast<std::size_t>(out.size());
  if (std::fseek(file, static_cast<long>(8 * offset_doubles), SEEK_SET) != 0 ||
      std::fread(out.data(), sizeof(double), count, file) != count) {
    throw Error(ErrorKind::kBadInput, "cannot read " + path_);
  }
  if constexpr (std::endian::native == std::endian::big) {
    for (double& value : out) {
      std::uint64_t bits;
      std::memcpy(&bits, &value, 8);
      bits = __builtin_bswap64(bits);
      std::memcpy(&value, &bits, 8);
    }
  }
}

RigidFrame RigidTrajectoryReader::read_frame(std::int64_t k) {
  const std::int64_t b = bodies_;
  RigidFrame frame;
  frame.state.resize(6 * b);
  frame.quantities.resize(6 * b + 1);
  if (k == 0) {
    frame.start.resize(4 * b);
    read_doubles(0, frame.state);
    read_doubles(6 * b, frame.start);
    read_doubles(10 * b, frame.quantities);
  } else {
    const std::int64_t at = (16 * b + 1) + (k - 1) * (12 * b + 1);
    read_doubles(at, frame.state);
    read_doubles(at + 6 * b, frame.quantities);
  }
  return frame;
}

State rigid_state_from_block(const SceneModel& model, const Vector& block) {
  const int n = model.num_particles();
  State state;
  state.q.resize(3 * n);
  state.v.resize(3 * n);
  for (int b = 0; b < n; ++b) {
    state.q.segment<3>(3 * b) = block.segment<3>(6 * b);
    if (model.fixed[b]) {
      state.v.segment<3>(3 * b).setZero();
    } else {
      state.v.segment<3>(3 * b) = block.segment<3>(6 * b + 3);
    }
  }
  return state;
}

}  // namespace fosssim
