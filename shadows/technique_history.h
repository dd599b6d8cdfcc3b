// What a technique keeps from one frame to the next of a sequence of frames (a fly-through,
// the repeated frames of a still view): the buffers it reuses instead of allocating them
// again, so that a frame in a steady state allocates nothing (a framebuffer, a map, rows of
// scratch), and results it may reuse while they stay valid (a virtual shadow map's pages,
// a temporal filter's past frames).
//
// Each technique keeps its own types: state<T>() is T's one instance in this history, made
// (default-constructed) on first use. A technique that runs another (contact shadows run the
// shadow map) finds the other's types beside its own. The caller keeps one history per light
// of one technique's series (frame/render.h, FrameHistory), so no two techniques, settings or
// lights ever share a T.
//
// States are values: a history copies (the timing protocol starts each measured frame from
// the same copy, app/common/timing.h), so T must be copyable, and a T must never point into
// the scene, which the next frame may have changed: it keeps what it needs to tell (a
// geometry's version, a light's position) and compares.
#pragma once

#include <any>
#include <map>
#include <typeindex>

namespace shadowlab {

class TechniqueHistory {
public:
    // T's state in this history, default-constructed on first use. Not thread-safe: call it
    // from the technique's own thread, before its parallel loops.
    template <class T>
    T& state() {
        std::any& slot = states_[std::type_index(typeid(T))];
        if (!slot.has_value()) slot.emplace<T>();
        return *std::any_cast<T>(&slot);
    }

    // How many types of state it keeps (0: a first frame).
    size_t size() const { return states_.size(); }

private:
    std::map<std::type_index, std::any> states_;
};

}  // namespace shadowlab
