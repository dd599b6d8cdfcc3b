#include "frame/overrides_json.h"

#include <optional>
#include <sstream>

namespace shadowlab {
namespace {

using Json = nlohmann::ordered_json;

template <class T>
void readOptional(const Json& j, const char* key, std::optional<T>& into) {
    if (j.contains(key)) into = j.at(key).get<T>();
}

void readOptional(const Json& j, const char* key, std::optional<glm::vec3>& into) {
    if (!j.contains(key)) return;
    const auto v = j.at(key).get<std::array<float, 3>>();
    into = glm::vec3(v[0], v[1], v[2]);
}

std::string point(const glm::vec3& v) {
    std::ostringstream text;
    text << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return text.str();
}

}  // namespace

Json overridesJson(const SceneOverrides& o) {
    Json j = Json::object();
    if (o.light) j["light"] = *o.light;
    if (o.width) j["width"] = *o.width;
    if (o.height) j["height"] = *o.height;
    if (o.eye) j["eye"] = xyz(*o.eye);
    if (o.target) j["target"] = xyz(*o.target);
    if (o.fovyDeg) j["fovy"] = *o.fovyDeg;
    if (o.lightPosition) j["light_position"] = xyz(*o.lightPosition);
    if (o.lightRadius) j["light_radius"] = *o.lightRadius;
    return j;
}

SceneOverrides readOverrides(const Json& j) {
    SceneOverrides o;
    readOptional(j, "light", o.light);
    readOptional(j, "width", o.width);
    readOptional(j, "height", o.height);
    readOptional(j, "eye", o.eye);
    readOptional(j, "target", o.target);
    readOptional(j, "fovy", o.fovyDeg);
    readOptional(j, "light_position", o.lightPosition);
    readOptional(j, "light_radius", o.lightRadius);
    return o;
}

std::string describeOverrides(const SceneOverrides& o) {
    std::ostringstream text;
    const auto add = [&](const std::string& part) { text << (text.tellp() > 0 ? ", " : "") << part; };
    if (o.light) add("light " + std::to_string(*o.light) + " alone");
    if (o.width || o.height)
        add((o.width ? std::to_string(*o.width) : "its") + " x " + (o.height ? std::to_string(*o.height) : "its") + " pixels");
    if (o.eye) add("eye at " + point(*o.eye));
    if (o.target) add("looking at " + point(*o.target));
    if (o.fovyDeg) add((std::ostringstream() << "vertical field of view " << *o.fovyDeg << " degrees").str());
    if (o.lightPosition) add("light at " + point(*o.lightPosition));
    if (o.lightRadius) add((std::ostringstream() << "light radius " << *o.lightRadius << " m").str());
    return text.tellp() > 0 ? text.str() : "the scene's own view and light";
}

}  // namespace shadowlab
