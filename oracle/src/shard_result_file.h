#pragma once
// Shard result files: one JSON file per shard of a sharded run, holding everything the reports
// need, so that `fosssim-oracle merge` writes the same reports as an unsharded run.

#include <string>
#include <vector>

#include "grading_run.h"

namespace fosssim {

/// The JSON text of a run or shard. Doubles are written so that they read back bit for bit;
/// NaN and infinities, which JSON lacks, as the strings "nan", "inf" and "-inf".
std::string shard_result_json(const GradingRun& run);

/// Reads a shard result file's text; `source` names it in messages. Throws Error (kBadInput).
GradingRun parse_shard_result(const std::string& text, const std::string& source);

/// Combines the shards of one run: they must all list the same scenes and the same shard count,
/// and hold every shard index from 1 to N exactly once, each with exactly its scenes. The result
/// is a 1/1 run with the results in the full list's order. Throws Error (kBadInput) saying what
/// does not fit.
GradingRun merge_shards(const std::vector<GradingRun>& shards,
                        const std::vector<std::string>& sources);

}  // namespace fosssim
