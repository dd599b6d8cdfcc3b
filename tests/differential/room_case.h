// The built-in room of differential rendering (differential/scene/compositing_cases.h) at a small size,
// preprocessed once per test program, with its bunny prepared (its levels and light).
#pragma once

#include <string>

#include "differential/composite.h"
#include "differential/scene/compositing_cases.h"
#include "scenes/obj_reader.h"
#include "scenes/scene_file.h"

namespace shadowlab::test {

inline CompositingScene smallRoomScene(RoomPath path = RoomPath::UnderDesk, int width = 128, int height = 80) {
    return compositingRoom(readObj(builtinDataDir() + "/meshes/bunny_low.obj"), path, width, height);
}

struct RoomCase {
    CompositingScene scene = smallRoomScene();
    DifferentialModel model = preprocess(scene);
    PreparedObject object = prepareObject(model, scene.objects);
};

inline const RoomCase& smallRoom() {
    static const RoomCase room;
    return room;
}

}  // namespace shadowlab::test
