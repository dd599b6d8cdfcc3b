// `shadowlab merge-sweep`: the JSON files of a sweep's shards (`sweep --shard i/n`) joined
// into the results of the unsharded run, rows in its order. They equal that run's in
// everything but the measured times (median_ms, min_ms and the stats' *_ms): the error
// figures, stats and references are the same bytes on every machine (docs/determinism.md),
// the times are each machine's own.
#pragma once

#include <string>
#include <vector>

#include "app/measure/sweep.h"

namespace shadowlab {

struct SweepShardFile {
    std::string path;        // named in errors
    SweepResults results;    // parseSweepJson() of the file
};

// Checks that the files are parts of one sweep (sweepDifference), all of one split into N
// shards, each shard given once and none missing, and that their rows hold every setting
// of the grid at every thread count once; throws std::runtime_error naming the file or
// the shard otherwise. The result is the whole sweep: shard 1 of 1.
SweepResults mergeSweepShards(const std::vector<SweepShardFile>& files);

}  // namespace shadowlab
