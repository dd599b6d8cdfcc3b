// What the extension's Python objects hold: the library's objects, shared so that any of them
// may outlive another (a frame history its prepared scene, a view of a buffer its frame), and
// guarded so that two Python threads may use them at once with the GIL released.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>

#include "frame/render.h"
#include "python/debug_readback.h"
#include "scenes/prepared_scene.h"

namespace shadowlab::python {

// A PreparedScene (Python's PreparedScene): frames render under a shared lock, and a change of
// its camera or lights (which PreparedScene allows between frames) takes the lock alone, so
// that it waits for the frames rendering and no frame sees half of it.
struct PreparedHandle {
    explicit PreparedHandle(Scene scene) : prepared(std::move(scene)) {}
    PreparedScene prepared;
    std::shared_mutex mutex;
};

// A FrameHistory (Python's FrameHistory): its frames render one at a time (mutex), and it
// keeps the prepared scene of its first frame alive, since the library's history names its
// scene by address.
struct HistoryHandle {
    FrameHistory history;
    std::shared_ptr<PreparedHandle> prepared;   // null before the first frame
    std::mutex mutex;
};

// A rendered frame (Python's Frame): the library's Frame and what it was rendered with. Its
// numpy views point into `frame` and keep this object alive.
struct RenderedFrame {
    Frame frame;
    std::string technique;
    std::map<std::string, std::string> settings;   // every setting, defaults included
    DebugReadback debug;                           // empty unless rendered with debug buffers
};

// One light's pass of a RenderedFrame (Python's LightPass), which keeps the frame alive.
struct PassView {
    std::shared_ptr<RenderedFrame> frame;
    size_t index = 0;   // into frame->frame.passes
    LightPass& pass() const { return frame->frame.passes[index]; }
};

}  // namespace shadowlab::python
