// `shadowlab composite`: which frames of the object's path a run composites.
#include <doctest/doctest.h>

#include <fstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/composite.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;

namespace {

// The room at a tiny size: one pass count, no reference, one untimed run a frame.
CompositeArgs tinyRoom(const test::ScratchDirectory& scratch) {
    CompositeArgs a;
    a.scene = "room";
    a.passes = {10};
    a.width = 48;
    a.height = 30;
    a.resolution = 32;
    a.reference = false;
    a.threads = 1;
    a.outDir = scratch.path.string();
    return a;
}

std::vector<int> compositedFrames(const test::ScratchDirectory& scratch) {
    std::ifstream in(scratch.path / "composite.json");
    REQUIRE(in.good());
    const nlohmann::json json = nlohmann::json::parse(in);
    std::vector<int> frames;
    for (const nlohmann::json& frame : json.at("frames")) frames.push_back(frame.at("frame"));
    return frames;
}

}  // namespace

TEST_CASE("composite: without --frames every frame of the path is composited, in order") {
    const test::ScratchDirectory scratch("composite_frames");
    const CompositeArgs a = tinyRoom(scratch);
    runCompositeCommand(a);
    const std::vector<int> frames = compositedFrames(scratch);
    REQUIRE(frames.size() > 1);
    for (size_t k = 0; k < frames.size(); ++k) CHECK(frames[k] == int(k));
    // The path has no frame past the last one run: the run covered all of it.
    CompositeArgs past = a;
    past.frames = {int(frames.size())};
    CHECK_THROWS_AS(runCompositeCommand(past), std::invalid_argument);
}
