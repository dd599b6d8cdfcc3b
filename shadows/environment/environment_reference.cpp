// reference-env: the exact light a surface reflects from the environment,
//
//     L_o(wo) = integral over the sphere of f(wi, wo) L_env(wi) V(wi) max(0, Ns . wi) dwi,
//
// estimated per pixel by multiple importance sampling (Veach and Guibas 1995) of two
// strategies, one sample of each per round with the balance heuristic, so a round adds
//
//     sum over s in {environment, BRDF} of f L V cos / (p_env(w_s) + p_brdf(w_s)),
//
// p_env the map's luminance (shading/environment/environment_distribution.h), p_brdf the
// material's lobes (shading/brdf_sampling.h), both stratified over the rounds by shifted
// (0, 2)-sequences, V an Embree ray to infinity (with the
// geometric normal's test and offset of every reference, shadows/reference/reference.h),
// the light per channel the casters let through (a cut-out's holes, translucent surfaces).
// L_env is the map's piecewise-constant function, the one every other integral here uses.
//
// Convergence is measured, not assumed: the samples are two independent halves, A and B
// (streams seeded apart), the image is their mean, and the stat `halves_rms_radiance` is
// RMS(Y_A - Y_B) / 2 over hit pixels, which estimates the RMS error of the mean's
// luminance (for independent halves E (A - B)^2 = 2 Var A = 4 Var((A + B) / 2)), and
// `halves_rms_percent` the same against the mean luminance. It falls as 1 / sqrt(samples).
// Every pixel draws the same count of numbers from its own stream (seed, pixel), so the
// image is the same bytes for any number of threads.
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/brdf_sampling.h"
#include "shading/environment/environment_distribution.h"
#include "shading/light_sampling.h"
#include "shading/shade.h"
#include "shading/surface_albedo.h"
#include "shadows/environment/environment_source.h"
#include "shadows/environment/environment_techniques.h"
#include "shadows/environment/light_contribution.h"
#include "shadows/reference/reference.h"
#include "shadows/reference/scene_rays.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

constexpr uint64_t kHalfSeeds[2] = {0x656e762d41ull, 0x656e762d42ull};   // "env-A", "env-B"

// One sample's term of a round, f L V cos / (p_env + p_brdf), but for V: 0 where it is 0
// whatever the casters do, else what the ray of `direction` has to find.
struct Term {
    glm::dvec3 fL{0.0};
    double cosine = 0.0, pdf = 0.0;
    int ray = -1;   // index among the traced directions; -1: the term is 0
};

// A thread's buffers for estimate(), reused from pixel to pixel.
struct Scratch {
    std::vector<Term> terms;
    std::vector<glm::dvec3> directions;
    ReferenceVisibility::RayBatch batch;
};

struct Integrand {
    const EnvironmentMap& map;
    const EnvironmentDistribution& environment;
    const ReferenceVisibility& rays;
    const Material& material;
    glm::vec3 albedo;   // the surface's at the pixel (shading/surface_albedo.h)
    glm::vec3 P, Ng, Ns, wo;

    // Queues the term of direction wi; 0 below either normal's plane.
    void add(const glm::dvec3& wi, Scratch& scratch) const {
        scratch.terms.push_back(term(wi, scratch.directions));
    }
    Term term(const glm::dvec3& wi, std::vector<glm::dvec3>& directions) const {
        const double cosine = glm::dot(glm::dvec3(Ns), wi);
        if (!(cosine > 0.0)) return {};
        const glm::ivec2 t = map.texelToward(wi);
        const glm::dvec3 L(map.at(t.x, t.y));
        const glm::dvec3 f(brdf(material, albedo, Ns, glm::vec3(wi), wo));
        if (glm::dot(f * L, glm::dvec3(1.0)) == 0.0) return {};
        const double pdf = (environment.empty() ? 0.0 : environment.pdf(wi)) +
                           brdfPdf(material, glm::dvec3(Ns), glm::dvec3(wo), wi);
        if (!(pdf > 0.0)) return {};
        directions.push_back(wi);
        return {f * L, cosine, pdf, int(directions.size()) - 1};
    }
    // f L V cos / pdf, V per channel what the casters let through its ray (holes,
    // translucent casters).
    static glm::dvec3 value(const Term& term, std::span<const glm::vec3> passed) {
        if (term.ray < 0) return glm::dvec3(0.0);
        const glm::dvec3 V(passed[size_t(term.ray)]);
        if (V == glm::dvec3(0.0)) return glm::dvec3(0.0);
        return term.fL * V * term.cosine / term.pdf;
    }
};

// One half's estimate: `rounds` rounds of one sample of each strategy. The two numbers
// that choose a texel (environment) and place a lobe's direction (BRDF) come from two
// (0, 2)-sequences, each shifted by its own random offset (shading/light_sampling.h), so the
// rounds stratify both strategies; the rest are independent. Every term is queued first and
// the rays traced together (reference.h's RayBatch); the sum runs in the rounds' order.
glm::dvec3 estimate(const Integrand& integrand, int rounds, Pcg32 rng, Scratch& scratch) {
    scratch.terms.clear(), scratch.directions.clear();
    const glm::dvec2 environmentShift(rng.nextDouble(), rng.nextDouble()), brdfShift(rng.nextDouble(), rng.nextDouble());
    for (int r = 0; r < rounds; ++r) {
        const glm::dvec2 texel = shiftedSobol02(uint32_t(r), environmentShift), lobe = shiftedSobol02(uint32_t(r), brdfShift);
        const glm::dvec4 ue(texel, rng.nextDouble(), rng.nextDouble());
        const glm::dvec3 ub(rng.nextDouble(), lobe);
        if (!integrand.environment.empty()) integrand.add(integrand.environment.sample(ue).direction, scratch);
        integrand.add(sampleBrdf(integrand.material, glm::dvec3(integrand.Ns), glm::dvec3(integrand.wo), ub).direction, scratch);
    }
    const std::span<const glm::vec3> passed =
        integrand.rays.directionsPassed(integrand.P, integrand.Ng, scratch.directions, scratch.batch);
    glm::dvec3 sum(0.0);
    for (const Term& term : scratch.terms) sum += Integrand::value(term, passed);
    return sum / double(rounds);
}

struct ExactIntegralSettings {
    int samples = 1024;   // per pixel and strategy, environment and BRDF (even: two halves)
};

const SettingsTable<ExactIntegralSettings>& exactIntegralSettingsTable() {
    static const auto table = SettingsTable<ExactIntegralSettings>().integer(
        "samples", member(&ExactIntegralSettings::samples), 2, 1 << 20,
        "samples per pixel of each strategy, environment and BRDF (even: two halves)");
    return table;
}

ShadowOutputs runExactIntegral(const ShadowInputs& in) {
    const int samples = exactIntegralSettingsTable().read(in.params).samples;
    if (samples % 2 != 0) throw std::invalid_argument("reference-env: samples must be even (two halves)");
    StageTimer timer;
    const EnvironmentMap& map = sceneEnvironment(in.prepared);
    const EnvironmentDistribution environment(map);
    const ReferenceVisibility& rays = sceneRays(in.casters());   // built by the scene's first frame
    timer.lap("bvh");
    const GBuffer& g = in.gbuffer;
    const glm::vec3 eye = in.camera().eye;
    ShadowOutputs out;
    out.radiance.assign(g.pixelCount(), glm::vec3(0.0f));
    std::vector<double> halvesDifference(g.pixelCount(), 0.0);
    const ProgressStage progress(in.progress, "environment reference: row", uint64_t(g.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        Scratch scratch;
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                if (!g.hit[k]) continue;
                const Material& material = in.scene().materials.at(g.material[k]);
                const Integrand integrand{map, environment, rays, material,
                                          surfaceAlbedo(material, in.scene().albedoTextures, g, k), g.position[k], g.normal[k], g.shadingNormal[k],
                                          glm::normalize(eye - g.position[k])};
                const glm::dvec3 a = estimate(integrand, samples / 2, Pcg32(kHalfSeeds[0], k), scratch);
                const glm::dvec3 b = estimate(integrand, samples / 2, Pcg32(kHalfSeeds[1], k), scratch);
                out.radiance[k] = glm::vec3(0.5 * (a + b));
                halvesDifference[k] = luminance(a) - luminance(b);
            }
            progress.advance();
        }
    });
    timer.lap("integration");
    for (const Light& light : in.scene().lights) {
        addSceneLight(g, in.scene().materials, in.scene().albedoTextures, eye, light, rays.visibility(g, light), LightPart::Lit, out.radiance);
    }
    timer.lap("scene_lights");

    double squares = 0.0, meanY = 0.0;
    uint64_t hits = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        squares += halvesDifference[k] * halvesDifference[k], hits += g.hit[k];
        meanY += luminance(glm::dvec3(out.radiance[k]));
    }
    const double halvesRms = hits ? 0.5 * std::sqrt(squares / double(hits)) : 0.0;
    meanY = hits ? meanY / double(hits) : 0.0;
    out.stats = {{"samples_count", double(samples)},
                 {"halves_rms_radiance", halvesRms},
                 {"halves_rms_percent", meanY > 0.0 ? 100.0 * halvesRms / meanY : 0.0}};
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

Technique environmentReferenceTechnique() {
    return {.name = "reference-env",
            .description = "exact environment light: the integral of BRDF, environment and Embree visibility by "
                           "multiple importance sampling, in two independent halves",
            .params = exactIntegralSettingsTable().specs(),
            .run = runExactIntegral,
            .referenceName = "reference-env",
            .output = TechniqueOutput::Radiance,
            .prepare = [](const PreparedScene& prepared, const PreparedScene&, const TechniqueParams&) {
                return prepareEnvironment(prepared);
            }};
}

}  // namespace shadowlab
