#include "scenes/gltf/gltf_materials.h"

#include <cmath>

#include "scenes/albedo_texture.h"

namespace shadowlab {
namespace {

glm::vec4 baseColorFactor(const GltfDocument& document, const tinygltf::Material& material, const std::string& field) {
    const std::vector<double>& f = material.pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4) document.fail(field, "must be 4 numbers");
    glm::vec4 factor;
    for (int c = 0; c < 4; ++c) {
        if (!(f[size_t(c)] >= 0.0 && f[size_t(c)] <= 1.0)) document.fail(field, "each must be in [0, 1]");
        factor[c] = float(f[size_t(c)]);
    }
    return factor;
}

// The decoded image of the base colour texture (RGBA, row 0 at the top, as glTF's images
// and our textures store them).
const tinygltf::Image& baseColorImage(const GltfDocument& document, const tinygltf::TextureInfo& info,
                                      const std::string& field) {
    if (info.texCoord != 0) document.fail(field + ".texCoord", "only TEXCOORD_0 is read");
    const auto& textures = document.model.textures;
    if (size_t(info.index) >= textures.size())
        document.fail(field + ".index", "names texture " + std::to_string(info.index) + ", but the file has " +
                                            std::to_string(textures.size()));
    const int source = textures[size_t(info.index)].source;
    const std::string textureField = "textures[" + std::to_string(info.index) + "].source";
    if (source < 0 || size_t(source) >= document.model.images.size())
        document.fail(textureField, "names no image of the file (image sources in extensions are not read)");
    const tinygltf::Image& image = document.model.images[size_t(source)];
    if (image.component != 4 || image.image.size() != 4 * size_t(image.width) * size_t(image.height))
        document.fail("images[" + std::to_string(source) + "]", "was not decoded");
    return image;
}

// One axis's wrap mode from a sampler's wrapS or wrapT (section 3.8.4).
TextureWrap wrapMode(const GltfDocument& document, int mode, const std::string& field) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
    }
    document.fail(field, "must be 33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT) or 10497 (REPEAT), got " +
                             std::to_string(mode));
}

// The wrap of the texture's sampler, REPEAT on both axes without one (section 3.8.4). Its
// filters are not read: every texture here is read at the nearest texel.
UvWrap samplerWrap(const GltfDocument& document, const tinygltf::TextureInfo& info) {
    const int sampler = document.model.textures[size_t(info.index)].sampler;
    if (sampler < 0) return {TextureWrap::Repeat, TextureWrap::Repeat};
    const auto& samplers = document.model.samplers;
    if (size_t(sampler) >= samplers.size())
        document.fail("textures[" + std::to_string(info.index) + "].sampler",
                      "names sampler " + std::to_string(sampler) + ", but the file has " + std::to_string(samplers.size()));
    const std::string field = "samplers[" + std::to_string(sampler) + "]";
    return {wrapMode(document, samplers[size_t(sampler)].wrapS, field + ".wrapS"),
            wrapMode(document, samplers[size_t(sampler)].wrapT, field + ".wrapT")};
}

std::string imageName(const GltfDocument& document, const tinygltf::TextureInfo& info) {
    return document.path + ": images[" + std::to_string(document.model.textures[size_t(info.index)].source) + "]";
}

// The base colour texture's alpha times the factor's, per texel.
AlphaTexture maskAlpha(const GltfDocument& document, const tinygltf::TextureInfo& info, float factorAlpha,
                       const std::string& field) {
    const tinygltf::Image& image = baseColorImage(document, info, field);
    AlphaTexture texture{imageName(document, info), image.width, image.height, {}, samplerWrap(document, info)};
    texture.alpha.resize(size_t(image.width) * size_t(image.height));
    for (size_t k = 0; k < texture.alpha.size(); ++k)
        texture.alpha[k] = float(image.image[4 * k + 3]) / 255.0f * factorAlpha;
    return texture;
}

// The base colour texture's colour, linear (section 3.9.2: sRGB-encoded, then multiplied by
// the factor, which the material's albedo keeps).
AlbedoTexture baseColorAlbedo(const GltfDocument& document, const tinygltf::TextureInfo& info, const std::string& field) {
    const tinygltf::Image& image = baseColorImage(document, info, field);
    AlbedoTexture texture = decodeAlbedoTexture(imageName(document, info), image.width, image.height, image.image, 4);
    texture.wrap = samplerWrap(document, info);
    return texture;
}

}  // namespace

GltfMaterial readGltfMaterial(const GltfDocument& document, int index) {
    GltfMaterial result;
    if (index < 0) {
        result.material.name = "glTF default";
        result.material.albedo = glm::vec3(1.0f);
        return result;
    }
    const std::string field = "materials[" + std::to_string(index) + "]";
    if (size_t(index) >= document.model.materials.size())
        document.fail(field, "does not exist: the file has " + std::to_string(document.model.materials.size()));
    const tinygltf::Material& material = document.model.materials[size_t(index)];
    Material& ours = result.material;
    ours.name = material.name.empty() ? field : material.name;
    const glm::vec4 factor = baseColorFactor(document, material, field + ".pbrMetallicRoughness.baseColorFactor");
    ours.albedo = glm::vec3(factor);
    const tinygltf::TextureInfo& texture = material.pbrMetallicRoughness.baseColorTexture;
    const std::string textureField = field + ".pbrMetallicRoughness.baseColorTexture";
    if (texture.index >= 0) result.albedoTexture = baseColorAlbedo(document, texture, textureField);
    if (material.alphaMode == "MASK") {
        const double cutoff = material.alphaCutoff;
        if (!(cutoff >= 0.0 && cutoff <= 1e30)) document.fail(field + ".alphaCutoff", "must be a number >= 0");
        // Alpha >= 0 always passes a cutoff of 0 (opaque), and never one over 1.
        if (cutoff > 1.0) {
            result.invisible = true;
        } else if (texture.index >= 0 && cutoff > 0.0) {
            ours.alphaCutoff = float(cutoff);
            result.alphaTexture = maskAlpha(document, texture, factor.a, textureField);
        } else {
            result.invisible = factor.a < float(cutoff);
        }
    } else if (material.alphaMode == "BLEND") {
        ours.opacity = factor.a;
    } else if (material.alphaMode != "OPAQUE") {
        document.fail(field + ".alphaMode", "must be OPAQUE, MASK or BLEND, got " + material.alphaMode);
    }
    return result;
}

}  // namespace shadowlab
