#include "shard_result_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "printable_text.h"
#include "scene_list.h"

namespace fosssim {

using json = nlohmann::ordered_json;

namespace {

/// Throws Error (kBadInput) with a message.
[[noreturn]] void fail(const std::string& problem) { throw Error(ErrorKind::kBadInput, problem); }

constexpr const char* kFormat = "fosssim-oracle-results";
constexpr int kVersion = 1;

json number_json(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

double number_from(const json& value) {
  if (value.is_string()) {
    const std::string text = value.get<std::string>();
    if (text == "nan") return std::nan("");
    if (text == "inf") return HUGE_VAL;
    if (text == "-inf") return -HUGE_VAL;
    throw std::invalid_argument("\"" + text + "\" is not a number");
  }
  return value.get<double>();
}

json result_json(const SceneResult& r) {
  json j = {{"name", printable_text(r.name)},
            {"extra_credit", r.extra_credit},
            {"integrator", printable_text(r.integrator)},
            {"dim", r.dim},
            {"particles", r.particles},
            {"steps", r.steps},
            {"dt", number_json(r.dt)},
            {"verdict", verdict_id(r.verdict)},
            {"reason", printable_text(r.reason)},
            {"details", printable_text(r.details)},
            {"stderr_tail", printable_text(r.stderr_tail)},
            {"run_seconds", number_json(r.run_seconds)},
            {"grade_seconds", number_json(r.grade_seconds)}};
  if (r.residuals) {
    j["residuals"] = {{"accumulated_position", number_json(r.residuals->accumulated_position)},
                      {"accumulated_velocity", number_json(r.residuals->accumulated_velocity)},
                      {"max_position", number_json(r.residuals->max_position)},
                      {"max_velocity", number_json(r.residuals->max_velocity)}};
  }
  if (r.first_divergence) {
    j["first_divergence"] = {
        {"step", r.first_divergence->step},
        {"particle", r.first_divergence->particle},
        {"object", r.first_divergence->object()},
        {"position_residual", number_json(r.first_divergence->position_residual)},
        {"velocity_residual", number_json(r.first_divergence->velocity_residual)}};
  }
  return j;
}

SceneResult result_from(const json& j) {
  SceneResult r;
  r.name = j.at("name").get<std::string>();
  r.extra_credit = j.at("extra_credit").get<bool>();
  r.integrator = j.at("integrator").get<std::string>();
  r.dim = j.at("dim").get<int>();
  r.particles = j.at("particles").get<int>();
  r.steps = j.at("steps").get<std::int64_t>();
  r.dt = number_from(j.at("dt"));
  const std::string verdict = j.at("verdict").get<std::string>();
  const auto parsed = verdict_from_id(verdict);
  if (!parsed) throw std::invalid_argument("unknown verdict \"" + verdict + "\" for " + r.name);
  r.verdict = *parsed;
  r.reason = j.at("reason").get<std::string>();
  r.details = j.at("details").get<std::string>();
  r.stderr_tail = j.at("stderr_tail").get<std::string>();
  r.run_seconds = number_from(j.at("run_seconds"));
  r.grade_seconds = number_from(j.at("grade_seconds"));
  if (j.contains("residuals")) {
    const json& s = j.at("residuals");
    r.residuals = Residuals{number_from(s.at("accumulated_position")),
                            number_from(s.at("accumulated_velocity")),
                            number_from(s.at("max_position")), number_from(s.at("max_velocity"))};
  }
  if (j.contains("first_divergence")) {
    const json& d = j.at("first_divergence");
    r.first_divergence = DivergencePoint{
        d.at("step").get<std::int64_t>(), d.at("particle").get<int>(),
        number_from(d.at("position_residual")), number_from(d.at("velocity_residual")),
        d.value("object", std::string("particle")) == "body"};
  }
  return r;
}

}  // namespace

std::string shard_result_json(const GradingRun& run) {
  json scenes = json::array();
  for (const SceneListing& s : run.scenes) {
    scenes.push_back({{"name", printable_text(s.name)}, {"extra_credit", s.extra_credit}});
  }
  json results = json::array();
  for (const SceneResult& r : run.results) results.push_back(result_json(r));
  const json document = {{"format", kFormat},
                         {"version", kVersion},
                         {"candidate", printable_text(run.candidate)},
                         {"shard", {{"index", run.shard.index}, {"count", run.shard.count}}},
                         {"wall_seconds", number_json(run.wall_seconds)},
                         {"sandboxed", run.sandboxed},
                         {"scenes", scenes},
                         {"results", results}};
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

GradingRun parse_shard_result(const std::string& text, const std::string& source) {
  try {
    const json document = json::parse(text);
    if (!document.is_object() || document.value("format", "") != kFormat) {
      fail(source + " is not a fosssim-oracle result file (no \"format\": \"" + kFormat + "\")");
    }
    if (document.at("version").get<int>() != kVersion) {
      fail(source + " has result format version " + document.at("version").dump() +
           "; this oracle reads version " + std::to_string(kVersion));
    }
    GradingRun run;
    run.candidate = document.at("candidate").get<std::string>();
    run.shard.index = document.at("shard").at("index").get<int>();
    run.shard.count = document.at("shard").at("count").get<int>();
    if (run.shard.count < 1 || run.shard.index < 1 || run.shard.index > run.shard.count) {
      fail(source + ": invalid shard " + std::to_string(run.shard.index) + "/" +
           std::to_string(run.shard.count));
    }
    run.wall_seconds = number_from(document.at("wall_seconds"));
    run.sandboxed = document.value("sandboxed", true);  // absent in files of older oracles
    for (const json& s : document.at("scenes")) {
      run.scenes.push_back({s.at("name").get<std::string>(), s.at("extra_credit").get<bool>()});
    }
    for (const json& r : document.at("results")) run.results.push_back(result_from(r));
    return run;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& error) {
    fail(source + ": not a valid result file: " + error.what());
  }
}

GradingRun merge_shards(const std::vector<GradingRun>& shards,
                        const std::vector<std::string>& sources) {
  if (shards.empty()) fail(std::string("no shard result files to merge"));
  const GradingRun& first = shards.front();
  const int count = first.shard.count;
  std::vector<const GradingRun*> by_index(static_cast<std::size_t>(count), nullptr);
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const GradingRun& shard = shards[s];
    if (shard.shard.count != count) {
      fail(sources[s] + " is shard " + std::to_string(shard.shard.index) + "/" +
           std::to_string(shard.shard.count) + ", but " + sources[0] + " is one of " +
           std::to_string(count));
    }
    if (shard.scenes != first.scenes) {
      fail(sources[s] + " lists other scenes than " + sources[0] +
           " (shards of different runs or of a changed suite)");
    }
    if (shard.candidate != first.candidate) {
      fail(sources[s] + " graded the candidate " + shard.candidate + ", but " + sources[0] +
           " graded " + first.candidate);
    }
    const GradingRun*& slot = by_index[static_cast<std::size_t>(shard.shard.index - 1)];
    if (slot != nullptr) {
      fail("shard " + std::to_string(shard.shard.index) + "/" + std::to_string(count) +
           " is given twice (" + sources[s] + ")");
    }
    slot = &shard;
  }
  std::string missing;
  for (int k = 0; k < count; ++k) {
    if (by_index[static_cast<std::size_t>(k)] == nullptr) {
      missing +=
          (missing.empty() ? "" : ", ") + std::to_string(k + 1) + "/" + std::to_string(count);
    }
  }
  if (!missing.empty()) fail("the shards " + missing + " are missing");

  GradingRun merged;
  merged.candidate = first.candidate;
  merged.scenes = first.scenes;
  std::vector<std::size_t> next(static_cast<std::size_t>(count), 0);
  for (const GradingRun* shard : by_index) {
    merged.wall_seconds += shard->wall_seconds;
    merged.sandboxed = merged.sandboxed && shard->sandboxed;
  }
  for (std::size_t i = 0; i < merged.scenes.size(); ++i) {
    const auto k = static_cast<std::size_t>(Shard::holding(i, count).index - 1);
    const GradingRun& shard = *by_index[k];
    if (next[k] >= shard.results.size() || shard.results[next[k]].name != merged.scenes[i].name) {
      fail("shard " + std::to_string(k + 1) + "/" + std::to_string(count) +
           " does not hold the result of " + merged.scenes[i].name + " where expected");
    }
    merged.results.push_back(shard.results[next[k]++]);
  }
  for (std::size_t k = 0; k < next.size(); ++k) {
    if (next[k] != by_index[k]->results.size()) {
      fail("shard " + std::to_string(k + 1) + "/" + std::to_string(count) +
           " holds more results than its scenes");
    }
  }
  return merged;
}

}  // namespace fosssim
