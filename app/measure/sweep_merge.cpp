#include "app/measure/sweep_merge.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "app/measure/sweep_json.h"

namespace shadowlab {
namespace {

// Every file of the same sweep and split, and every shard of the split given once.
void checkShards(const std::vector<SweepShardFile>& files) {
    const SweepShardFile& first = files.front();
    const int count = first.results.shard.count;
    std::map<int, const std::string*> given;   // shard index -> its file
    for (const SweepShardFile& file : files) {
        if (const std::string difference = sweepDifference(file.results, first.results); !difference.empty())
            throw std::runtime_error(file.path + ": not a shard of the same sweep as " + first.path + " (" + difference + ")");
        const SweepShard& shard = file.results.shard;
        if (shard.count != count)
            throw std::runtime_error(file.path + " is shard " + shard.name() + " but " + first.path + " is shard " +
                                     first.results.shard.name() + ": shards of one split have the same N");
        if (const auto [at, added] = given.emplace(shard.index, &file.path); !added)
            throw std::runtime_error("shard " + shard.name() + " is given twice: " + *at->second + " and " + file.path);
    }
    if (given.size() == size_t(count)) return;
    // The first few missing, found within files.size() + kListed steps however large N is.
    constexpr int kListed = 8;
    std::string missing;
    for (int index = 1, listed = 0; index <= count && listed < kListed; ++index) {
        if (given.contains(index)) continue;
        missing += (missing.empty() ? "" : ", ") + SweepShard{index, count}.name();
        ++listed;
    }
    const size_t absent = size_t(count) - given.size();
    if (absent > size_t(kListed)) missing += " and " + std::to_string(absent - size_t(kListed)) + " more";
    throw std::runtime_error("missing shard(s) " + missing + " of the sweep of " + first.path);
}

std::string cell(uint64_t setting, int threads) {
    return "setting " + std::to_string(setting) + " at " + std::to_string(threads) + " threads";
}

// All rows in the unsharded order: by setting, and within one setting (all from one file)
// by thread count as run. Each setting of the grid must appear once at every thread count.
std::vector<SweepRow> joinRows(const std::vector<SweepShardFile>& files, const SweepGrid& grid) {
    std::vector<SweepRow> rows;
    for (const SweepShardFile& file : files) rows.insert(rows.end(), file.results.rows.begin(), file.results.rows.end());
    std::ranges::stable_sort(rows, {}, &SweepRow::setting);
    const auto requireNoRepeat = [&](size_t k) {
        if (k > 0 && k < rows.size() && rows[k].setting == rows[k - 1].setting && rows[k].threads == rows[k - 1].threads)
            throw std::runtime_error("the shards hold " + cell(rows[k].setting, rows[k].threads) + " twice (a file edited?)");
    };
    size_t at = 0;
    for (uint64_t setting = 0; setting < grid.settings; ++setting) {
        for (int threads : grid.threads) {
            requireNoRepeat(at);
            if (at == rows.size() || rows[at].setting != setting || rows[at].threads != threads)
                throw std::runtime_error("the shards lack " + cell(setting, threads) + " (a file cut short or edited?)");
            ++at;
        }
    }
    requireNoRepeat(at);
    if (at != rows.size())
        throw std::runtime_error("the shards hold " + cell(rows[at].setting, rows[at].threads) + ", which the grid lacks");
    return rows;
}

}  // namespace

SweepResults mergeSweepShards(const std::vector<SweepShardFile>& files) {
    if (files.empty()) throw std::invalid_argument("merge-sweep: give the JSON file of every shard");
    checkShards(files);
    SweepResults merged = files.front().results;
    merged.shard = {};
    merged.rows = joinRows(files, merged.grid);
    return merged;
}

}  // namespace shadowlab
