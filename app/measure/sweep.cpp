#include "app/measure/sweep.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>

#include <tbb/info.h>

#include "app/common/csv.h"
#include "app/common/output_files.h"
#include "app/common/timing.h"
#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"

namespace shadowlab {
namespace {

const char* const kShardRule = "expected I/N with 1 <= I <= N (I counts from 1, as SLURM_ARRAY_TASK_ID with --array=1-N)";

// The plans with only the shard's settings.
std::vector<SweepPlan> shardOf(std::vector<SweepPlan> plans, const SweepShard& shard) {
    if (!shard.valid()) throw std::invalid_argument("shard " + shard.name() + ": " + kShardRule);
    checkShardCount(shard.count, settingCount(plans));
    for (SweepPlan& plan : plans) std::erase_if(plan.settings, [&](const PlannedSetting& s) { return !shard.holds(s.index); });
    return plans;
}

std::vector<int> threadCounts(const SweepOptions& options) {
    if (options.threads.empty()) return {tbb::info::default_concurrency()};
    // A library caller (Python) has no CLI check before this one.
    if (const std::optional<int> n = badThreadCount(options.threads)) {
        if (*n < 1 || *n > kMaxThreads)
            throw std::invalid_argument("thread counts must be within 1.." + std::to_string(kMaxThreads) + ", got " +
                                        std::to_string(*n));
        throw std::invalid_argument("thread count " + std::to_string(*n) + " is given twice");
    }
    return options.threads;
}

// The reference a technique is scored against: the sweep's, or the one it names.
const std::string& referenceFor(const Technique& technique, const SweepOptions& options) {
    return options.reference.empty() ? technique.referenceName : options.reference;
}

// Errors and stats come from the last measured frame, its stage times medians (timeFrames).
SweepRow measure(const PreparedScene& prepared, const ScoredReference& reference, const Technique& technique,
                 const FrameSettings& settings, const SweepOptions& options, const ProgressStage& frames) {
    const TimedFrames timed = timeFrames(prepared, technique, settings, options.warmupRuns, options.runs, frames);
    SweepRow row;
    row.technique = technique.name;
    row.reference = referenceFor(technique, options);
    row.settings = settings.params;
    row.medianMs = timed.timing.medianMs;
    row.minMs = timed.timing.minMs;
    const ImageChannels scored = scoredImage(timed.last);
    row.errors = scoreFrame(reference, scored, timed.last);
    if (timed.last.passes.size() > 1) row.lightErrors = scoreLights(reference.scored, scored);
    row.stats = timed.last.shadow.stats;
    return row;
}

// Every stat name any row reports, in the order first seen.
std::vector<std::string> statNames(const SweepResults& results) {
    std::vector<std::string> names;
    for (const SweepRow& row : results.rows)
        for (const TechniqueStat& s : row.stats)
            if (std::ranges::find(names, s.name) == names.end()) names.push_back(s.name);
    return names;
}

// Each light's headline figures in the CSV: misclassified pixels for hard shadows, the RMS
// for any, umbra lit for soft ones (docs/soft-shadows.md).
struct LightCsvFigure {
    const char* name;
    double (*value)(const ErrorFigures&);
};
constexpr LightCsvFigure kLightCsvFigures[] = {
    {"misclassified_percent", [](const ErrorFigures& e) { return e.percentOfPixels(e.misclassified()); }},
    {"rms", [](const ErrorFigures& e) { return e.rms; }},
    {"umbra_lit_percent", [](const ErrorFigures& e) { return e.percentOfPixels(e.umbraLit); }},
};

// The error columns of the text table, for a row or one of its lights.
std::string errorColumns(const ErrorFigures& e) {
    char fullUmbraLit[32] = "not recorded";
    if (const std::optional<double> percent = e.fullUmbraLitPercent())
        std::snprintf(fullUmbraLit, sizeof fullUmbraLit, "%.4f", *percent);
    char flip[32] = "";   // a light of several has none: FLIP is of the whole shaded image
    if (e.flipMean) std::snprintf(flip, sizeof flip, "%.5f", *e.flipMean);
    char line[256];
    std::snprintf(line, sizeof line, "%14.4f %10.5f %10.5f %11.4f %16s %12.4f %13.4f %10s\n",
                  e.percentOfPixels(e.misclassified()), e.rms, e.maxAbs, e.percentOfPixels(e.umbraLit), fullUmbraLit,
                  e.percentOfPixels(e.umbraOver), e.percentOfPixels(e.litShadowed), flip);
    return line;
}

std::string statValue(const SweepRow& row, const std::string& name) {
    const auto stat = std::ranges::find(row.stats, name, &TechniqueStat::name);
    return stat == row.stats.end() ? "" : csvNumber(stat->value);
}

// A reference as the settings are scored against it, and its pictures (with imagesOutDir).
struct RenderedReference : ScoredReference {
    FrameImages images;
};

// Each reference the techniques are scored against, rendered once.
// With a pictures folder (else empty), each reference's pictures are written into it.
std::map<std::string, RenderedReference> renderReferences(const PreparedScene& prepared,
                                                          const std::vector<SweepPlan>& plans,
                                                          const SweepOptions& options,
                                                          const std::filesystem::path& folder) {
    std::map<std::string, RenderedReference> references;
    for (const SweepPlan& plan : plans) {
        const std::string& name = referenceFor(*plan.technique, options);
        if (references.contains(name)) continue;
        const Frame frame = renderReferenceFrame(prepared, options.simd, name, options.progress);
        FrameImages images;
        if (!folder.empty()) images = writeFramePictures(options.imagesOutDir, folder, name, frame, nullptr);
        references.emplace(name, RenderedReference{scoredReference(frame), std::move(images)});
    }
    return references;
}

// A setting's pictures, from one more untimed frame that also writes its debug buffers:
// the frames are deterministic, so they are those of the timed frames.
FrameImages writeSettingPictures(const PreparedScene& prepared, const Technique& technique,
                                 const PlannedSetting& setting, const RenderedReference& reference,
                                 const SweepOptions& options, const std::filesystem::path& folder) {
    const std::string name = "setting-" + std::to_string(setting.index);
    const std::filesystem::path& base = options.imagesOutDir;
    const std::filesystem::path debugDir = folder / (name + "-debug");
    const Frame frame = renderFrame(prepared, technique, {options.simd, setting.params, debugDir});
    FrameImages images = writeFramePictures(base, folder, name, frame, &reference.scored);
    images.referenceImage = reference.images.image;
    images.referenceVisibility = reference.images.visibility;
    images.debugBuffers = debugPictures(base, debugDir, technique.name);
    return images;
}

// The grid the whole sweep covers, as every shard of it describes it.
SweepGrid describeGrid(const std::vector<SweepPlan>& plans, const std::vector<int>& threads,
                       const std::map<std::string, RenderedReference>& references, const SweepOptions& options) {
    SweepGrid grid{options.axes, options.overrides, options.reference, {}, threads, options.warmupRuns, options.runs,
                   settingCount(plans)};
    for (const auto& [name, reference] : references)
        grid.referenceFingerprints[name] = referenceFingerprint(reference.scored);
    return grid;
}

// What a sweep's options ask for, checked before anything renders: the whole grid, the
// shard's part of it and the thread counts.
struct SweepWork {
    std::vector<SweepPlan> grid, plans;
    std::vector<int> threads;
};
SweepWork planWork(const SweepOptions& options) {
    if (options.techniques.empty()) throw std::invalid_argument("sweep: give at least one technique");
    if (!runsInRange(options.runs, options.warmupRuns))
        throw std::invalid_argument("sweep: runs must be within 1.." + std::to_string(kMaxRuns) + ", warm-up runs 0.." +
                                    std::to_string(kMaxWarmupRuns));
    if (!options.reference.empty()) findTechnique(options.reference);   // a typo fails before the long part
    std::vector<SweepPlan> grid = planSweep(options.techniques, options.axes);
    std::vector<SweepPlan> plans = shardOf(grid, options.shard);
    return {std::move(grid), std::move(plans), threadCounts(options)};
}

}  // namespace

void checkShardCount(int64_t count, uint64_t settings) {
    if (count < 1 || uint64_t(count) > settings)
        throw std::invalid_argument(std::to_string(count) + " shards: the sweep has only " + std::to_string(settings) +
                                    " settings, so some shards would have none (use 1 to " + std::to_string(settings) +
                                    " shards)");
}

std::optional<int> badThreadCount(const std::vector<int>& threads) {
    for (auto n = threads.begin(); n != threads.end(); ++n)
        if (*n < 1 || *n > kMaxThreads || std::find(threads.begin(), n, *n) != n) return *n;
    return std::nullopt;
}

bool runsInRange(int runs, int warmupRuns) {
    return runs >= 1 && runs <= kMaxRuns && warmupRuns >= 0 && warmupRuns <= kMaxWarmupRuns;
}

std::string SweepRow::settingsLabel() const { return shadowlab::settingsLabel(settings); }

SweepShard parseSweepShard(const std::string& text) {
    // Digits only: from_chars alone would take "1/3x" or a sign.
    const size_t slash = text.find('/');
    const auto number = [&](size_t from, size_t to, int& value) {
        const char* first = text.data() + from;
        const char* last = text.data() + to;
        return first != last && std::all_of(first, last, [](char c) { return c >= '0' && c <= '9'; }) &&
               std::from_chars(first, last, value).ec == std::errc{};
    };
    SweepShard shard{0, 0};
    if (slash == std::string::npos || !number(0, slash, shard.index) || !number(slash + 1, text.size(), shard.count) ||
        !shard.valid())
        throw std::invalid_argument("--shard " + text + ": " + kShardRule);
    return shard;
}

namespace {

// The sweep of `work` (planWork(options)), planned once by either entry point.
SweepResults runPlannedSweep(Scene scene, const SweepOptions& options, const SweepWork& work) {
    const std::vector<SweepPlan>& grid = work.grid;
    const std::vector<SweepPlan>& plans = work.plans;
    const std::vector<int>& threads = work.threads;
    applyOverrides(scene, options.overrides);
    const PreparedScene prepared(std::move(scene));
    checkSettings(prepared, plans, options.simd, options.progress, "sweep");
    SweepResults results{prepared.scene().name, {}, {}, options.shard, {}};
    for (const SweepPlan& plan : grid) results.techniques.push_back(plan.technique->name);
    const std::filesystem::path folder =
        options.imagesOutDir.empty() ? std::filesystem::path() : options.imagesOutDir / sweepImagesFolder(results);
    // Every reference of the grid, not only the shard's: the shards' fingerprints must agree.
    const std::map<std::string, RenderedReference> references = renderReferences(prepared, grid, options, folder);
    results.grid = describeGrid(grid, threads, references, options);
    const ProgressStage frames(options.progress, "sweep: frame",
                               settingCount(plans) * threads.size() * uint64_t(options.warmupRuns + options.runs));
    for (const SweepPlan& plan : plans) {
        const RenderedReference& reference = references.at(referenceFor(*plan.technique, options));
        for (const PlannedSetting& setting : plan.settings) {
            const size_t first = results.rows.size();
            for (int n : threads) {
                SweepRow row = withThreads(n, [&] {
                    return measure(prepared, reference, *plan.technique, {options.simd, setting.params, {}},
                                   options, frames);
                });
                row.setting = setting.index;
                row.threads = n;
                results.rows.push_back(std::move(row));
            }
            if (folder.empty()) continue;
            const FrameImages images =
                writeSettingPictures(prepared, *plan.technique, setting, reference, options, folder);
            for (size_t k = first; k < results.rows.size(); ++k) results.rows[k].images = images;
        }
    }
    return results;
}

}  // namespace

SweepResults runSweep(const SweepOptions& options) {
    // A mistake in the options is reported before the scene file is read.
    const SweepWork work = planWork(options);
    return runPlannedSweep(loadScene(options.scene), options, work);
}

SweepResults runSweep(Scene scene, const SweepOptions& options) {
    return runPlannedSweep(std::move(scene), options, planWork(options));
}

std::string referenceFingerprint(const ImageChannels& reference) {
    uint64_t hash = 0xcbf29ce484222325ull;
    const auto mix = [&hash](const void* data, size_t bytes) {
        for (size_t k = 0; k < bytes; ++k) hash = (hash ^ static_cast<const uint8_t*>(data)[k]) * 0x100000001b3ull;
    };
    const int size[2] = {reference.width, reference.height};
    mix(size, sizeof size);
    for (size_t c = 0; c < reference.names.size(); ++c) {
        mix(reference.names[c].c_str(), reference.names[c].size() + 1);   // with its NUL: a name ends before the data
        mix(reference.data[c].data(), reference.data[c].size() * sizeof(float));
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

size_t SweepResults::lightCount() const {
    size_t count = 0;
    for (const SweepRow& row : rows) count = std::max(count, row.lightErrors.size());
    return count;
}

std::string sweepFileStem(const SweepResults& results) {
    const SweepShard& shard = results.shard;
    return results.scene + "-" + techniqueListStem(results.techniques) +
           (shard.count > 1 ? "-shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) : "");
}

std::string sweepImagesFolder(const SweepResults& results) { return sweepFileStem(results) + "-images"; }

std::string formatSweepText(const SweepResults& results) {
    std::string text = results.scene + (results.shard.count > 1 ? ", shard " + results.shard.name() : "") + "\n";
    char line[512];
    std::snprintf(line, sizeof line, "%-16s %-40s %7s %10s %10s %14s %10s %10s %11s %16s %12s %13s %10s\n", "technique",
                  "settings", "threads", "median ms", "min ms", "misclassified%", "RMS", "max", "umbra lit%",
                  "umbra lit 0.02%", "umbra over%", "lit shadowed%", "FLIP");
    text += line;
    for (const SweepRow& r : results.rows) {
        std::snprintf(line, sizeof line, "%-16s %-40s %7d %10.3f %10.3f ", r.technique.c_str(),
                      r.settingsLabel().c_str(), r.threads, r.medianMs, r.minMs);
        text += line + errorColumns(r.errors);
        for (size_t k = 0; k < r.lightErrors.size(); ++k) {
            std::snprintf(line, sizeof line, "%-16s %-40s %7s %10s %10s ", ("  light " + std::to_string(k)).c_str(),
                          "", "", "", "");
            text += line + errorColumns(r.lightErrors[k]);
        }
    }
    return text;
}

std::string formatSweepCsv(const SweepResults& results) {
    const std::vector<std::string> stats = statNames(results);
    std::vector<std::string> header = {"technique", "settings", "threads", "median_ms", "min_ms", "rms", "rms_display", "mean_abs",
                                       "max_abs", "misclassified_percent", "false_shadow_percent", "false_light_percent",
                                       "umbra_lit_percent", "full_umbra_lit_percent", "umbra_over_percent",
                                       "lit_shadowed_percent", "reference", "flip_mean"};
    const size_t lights = results.lightCount();
    for (size_t k = 0; k < lights; ++k)
        for (const LightCsvFigure& figure : kLightCsvFigures)
            header.push_back("light" + std::to_string(k) + "_" + figure.name);
    header.insert(header.end(), stats.begin(), stats.end());
    std::string csv = csvLine(header);
    for (const SweepRow& r : results.rows) {
        const ErrorFigures& e = r.errors;
        std::vector<std::string> fields = {r.technique, r.settingsLabel(), std::to_string(r.threads),
                                           csvNumber(r.medianMs), csvNumber(r.minMs), csvNumber(e.rms),
                                           e.rmsDisplay ? csvNumber(*e.rmsDisplay) : "", csvNumber(e.meanAbs),
                                           csvNumber(e.maxAbs), csvNumber(e.percentOfPixels(e.misclassified())),
                                           csvNumber(e.percentOfPixels(e.falseShadow)), csvNumber(e.percentOfPixels(e.falseLight)),
                                           csvNumber(e.percentOfPixels(e.umbraLit)),
                                           e.fullUmbraRecorded ? csvNumber(*e.fullUmbraLitPercent()) : "",
                                           csvNumber(e.percentOfPixels(e.umbraOver)),
                                           csvNumber(e.percentOfPixels(e.litShadowed)),
                                           r.reference, e.flipMean ? csvNumber(*e.flipMean) : ""};
        for (size_t k = 0; k < lights; ++k)
            for (const LightCsvFigure& figure : kLightCsvFigures)
                fields.push_back(k < r.lightErrors.size() ? csvNumber(figure.value(r.lightErrors[k])) : "");
        for (const std::string& name : stats) fields.push_back(statValue(r, name));
        csv += csvLine(fields);
    }
    return csv;
}

}  // namespace shadowlab
