// Natural light with shadows (DeCoro and Rusinkiewicz 2008; docs/subtractive-shadows.md):
// techniques that light the scene by its environment map and return a radiance image
// (TechniqueOutput::Radiance), scored on its luminance against `reference-env`.
//
//   env-additive         the sum over N lights sampled from the environment of each light's
//                        BRDF-weighted contribution times its visibility: the baseline;
//   env-subtractive      the unshadowed light C from fast local illumination, less each
//                        light's contribution where it is occluded, S, computed at a chosen
//                        sampling detail and resampled (the paper's technique);
//   reference-env-lights env-additive with 1000 lights and exact visibility (the paper's
//                        reference images, Figure 3);
//   reference-env        the exact environment integral with the BRDF and exact visibility,
//                        by multiple importance sampling (environment_reference.cpp).
//
// Each also lights the scene by every light the scene file has, additively, with the same
// visibility (the paper's section 4).
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique environmentAdditiveTechnique();
Technique environmentLightsReferenceTechnique();
Technique environmentSubtractiveTechnique();
Technique environmentReferenceTechnique();

}  // namespace shadowlab
