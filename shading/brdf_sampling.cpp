#include "shading/brdf_sampling.h"

#include <algorithm>
#include <cmath>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"
#include "shading/luminance.h"
#include "shading/microfacet_ggx.h"

namespace shadowlab {
namespace {

double diffuseShare(const Material& m) {
    if (m.model == MaterialModel::Lambert) return 1.0;
    const double d = luminance(glm::dvec3(m.albedo)), s = luminance(glm::dvec3(m.specular));
    return d + s > 0.0 ? d / (d + s) : 1.0;
}

// A unit vector at polar angle theta (given by its cosine) and azimuth phi about `axis`,
// in the branchless orthonormal basis of Duff et al., JCGT 6(1), 2017.
glm::dvec3 aroundAxis(const glm::dvec3& axis, double cosTheta, double phi) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1.0 / (sign + axis.z), b = axis.x * axis.y * a;
    const glm::dvec3 t(1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
    const glm::dvec3 s(b, sign + axis.y * axis.y * a, -axis.y);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return glm::normalize(sinTheta * (portable::cos(phi) * t + portable::sin(phi) * s) + cosTheta * axis);
}

glm::dvec3 mirror(const glm::dvec3& w, const glm::dvec3& about) { return 2.0 * glm::dot(w, about) * about - w; }

// A power-cosine lobe (n + 1) / (2 pi) cos^n about an axis: cos theta = u^(1 / (n + 1)).
double powerCosinePdf(double exponent, double cosTheta) {
    return cosTheta > 0.0 ? (exponent + 1.0) / (2.0 * kPi) * portable::pow(cosTheta, exponent) : 0.0;
}

// The half vector's density about N, for the two half-vector lobes.
double halfVectorPdf(const Material& m, double cosH) {
    if (m.model == MaterialModel::BlinnPhong) return powerCosinePdf(m.shininess, cosH);
    return ggxDistribution(cosH, double(m.roughness)) * std::max(0.0, cosH);
}

double specularPdf(const Material& m, const glm::dvec3& N, const glm::dvec3& wo, const glm::dvec3& wi) {
    switch (m.model) {
        case MaterialModel::Lambert: return 0.0;
        case MaterialModel::Phong: return powerCosinePdf(m.shininess, glm::dot(mirror(wo, N), wi));
        case MaterialModel::BlinnPhong:
        case MaterialModel::Ggx: {
            const glm::dvec3 sum = wi + wo;
            if (glm::dot(sum, sum) == 0.0) return 0.0;
            // wi was reflected about the half vector on N's side, whichever sign wo . h had.
            glm::dvec3 h = glm::normalize(sum);
            if (glm::dot(N, h) < 0.0) h = -h;
            const double cosVH = std::abs(glm::dot(wo, h));
            return cosVH > 0.0 ? halfVectorPdf(m, glm::dot(N, h)) / (4.0 * cosVH) : 0.0;
        }
    }
    return 0.0;
}

glm::dvec3 sampleSpecular(const Material& m, const glm::dvec3& N, const glm::dvec3& wo, double u1, double u2) {
    const double phi = 2.0 * kPi * u2;
    switch (m.model) {
        case MaterialModel::Lambert: break;
        case MaterialModel::Phong:
            return aroundAxis(mirror(wo, N), portable::pow(1.0 - u1, 1.0 / (double(m.shininess) + 1.0)), phi);
        case MaterialModel::BlinnPhong:
            return mirror(wo, aroundAxis(N, portable::pow(1.0 - u1, 1.0 / (double(m.shininess) + 1.0)), phi));
        case MaterialModel::Ggx: {
            const double alpha2 = double(m.roughness) * double(m.roughness);
            const double tan2 = alpha2 * u1 / (1.0 - u1);
            return mirror(wo, aroundAxis(N, 1.0 / std::sqrt(1.0 + tan2), phi));
        }
    }
    return N;
}

}  // namespace

double brdfPdf(const Material& material, const glm::dvec3& N, const glm::dvec3& wo, const glm::dvec3& wi) {
    const double share = diffuseShare(material);
    const double diffuse = std::max(0.0, glm::dot(N, wi)) / kPi;
    return share * diffuse + (1.0 - share) * specularPdf(material, N, wo, wi);
}

BrdfSample sampleBrdf(const Material& material, const glm::dvec3& N, const glm::dvec3& wo, const glm::dvec3& u) {
    BrdfSample s;
    if (u.x < diffuseShare(material)) {
        // Cosine-weighted: cos theta = sqrt(1 - u), so that p = cos theta / pi.
        s.direction = aroundAxis(N, std::sqrt(1.0 - u.y), 2.0 * kPi * u.z);
    } else {
        s.direction = sampleSpecular(material, N, wo, u.y, u.z);
    }
    s.pdf = brdfPdf(material, N, wo, s.direction);
    return s;
}

}  // namespace shadowlab
