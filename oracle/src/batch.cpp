#include "batch.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

#include "child_process.h"

namespace fosssim {

void for_each_in_parallel(std::size_t count, int jobs,
                          const std::function<void(std::size_t)>& work) {
  std::atomic<std::size_t> next{0};
  const auto worker = [&]() {
    for (std::size_t i = next++; i < count; i = next++) work(i);
  };
  const std::size_t threads =
      std::min<std::size_t>(std::max(jobs, 1), std::max<std::size_t>(count, 1));
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
}

std::vector<SceneResult> grade_scenes(const std::vector<SceneEntry>& scenes,
                                      const GradingOptions& options, int jobs,
                                      const SceneFinished& on_finished) {
  std::vector<SceneResult> results(scenes.size());
  std::mutex report_mutex;
  std::size_t done = 0;
  for_each_in_parallel(scenes.size(), jobs, [&](std::size_t i) {
    if (children_stopped()) {
      results[i].name = scenes[i].name;
      results[i].extra_credit = scenes[i].extra_credit;
      results[i].verdict = Verdict::kInterrupted;
      results[i].reason = "not run: the oracle was interrupted";
    } else {
      results[i] = grade_scene(scenes[i], options);
    }
    std::lock_guard<std::mutex> lock(report_mutex);
    ++done;
    if (on_finished) on_finished(results[i], done, scenes.size());
  });
  return results;
}

}  // namespace fosssim
