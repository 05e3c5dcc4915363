// glTF metallic-roughness BSDF in the local shading frame (z = shading
// normal), shared by GLSL and C++. The caller flips the normal to the side of
// wo, so wo.z > 0; a wi with wi.z < 0 has f and pdf of the thin-walled
// transmission only (0 without KHR_materials_transmission).
//
// The glTF 2.0 specification's reference model (appendix B), with
// KHR_materials_specular's weight s on the dielectric layer:
//   f = (1 - metallic) * dielectric + metallic * metal
//   dielectric = (1 - s Fd(wo.h)) * baseColor / pi + s Fd(wo.h) * D(h) V(wo, wi)
//   metal = Fm(wo.h) * D(h) V(wo, wi)
//     D: GGX (Trowbridge-Reitz), alpha = max(roughness^2, kMinGgxAlpha)
//     V: Smith height-correlated G2 / (4 wo.z wi.z)
//     Fd: Schlick with F0 = 0.04 (ior 1.5); Fm: Schlick with F0 = baseColor
//
// This is the specification's model as written, not an energy-compensated
// variant: a rough white dielectric reflects at most 1 (test
// Bsdf.WhiteAlbedoIsAtMostOne), and other glTF viewers render the same
// model, so scenes come out as bright as their authors saw them. The
// diffuse lobe's weight 1 - s Fd(wo.h) depends on wi only through the half
// vector; its cosine-weighted mean over wi has no closed form and is fitted
// (meanSchlickWeightOverCosine), which is all lobe selection and the
// Q-learning estimate need.
//
// The alpha floor (1e-3, i.e. roughness ~0.03) keeps D and its sampling finite
// in float; D is written with x^2 + y^2 instead of 1 - z^2 to avoid
// cancellation near the peak.
#ifndef QLIGHT_SHARED_BSDF_H
#define QLIGHT_SHARED_BSDF_H

#include "common.h"
#include "sampling.h"

QL_BEGIN

// False where every material is exactly Lambertian (metallic 0, specular 0, no
// transmission): the functions below return the Lambertian values at once, which is
// what the full model gives there, and the microfacet code is compiled out. The
// GLSL path passes define it as a specialization constant (on lavapipe every branch
// side runs, so code left in costs whatever the branch).
#ifndef QL_BSDF_MICROFACET
#define QL_BSDF_MICROFACET true
#endif

QL_CONST float kMinGgxAlpha = 1e-3f;
QL_CONST float kDielectricF0 = 0.04f;

// specular: KHR_materials_specular's specularFactor, the weight of the
// dielectric specular layer (1 = plain glTF). At 0 with metallic 0 the
// material is exactly Lambertian (baseColor / pi): the furnace test and the
// exact Q-learning transport of Lambertian vertices rely on that.
// transmission: KHR_materials_transmission's factor, the share of the diffuse
// base replaced by a thin-walled microfacet BTDF (no volume: the light leaves
// the far side undeflected, blurred by the roughness); ior: KHR_materials_ior,
// the dielectric F0 = ((ior - 1) / (ior + 1))^2 (1.5: 0.04).
struct BsdfParams {
  vec3 baseColor;
  float metallic;
  float roughness;
  float specular;
  float transmission;
  float ior;
  // 0: thin-walled transmission; else refraction (KHR_materials_volume) with this relative
  // index, wi's side over wo's: ior entering the solid, 1 / ior leaving it.
  float eta;
};

QL_FN float dielectricF0(BsdfParams p) {
  float r = (p.ior - 1.0f) / (p.ior + 1.0f);
  return r * r;
}

QL_FN float ggxAlpha(float roughness) { return max(roughness * roughness, kMinGgxAlpha); }

QL_FN float schlickWeight(float cosTheta) {
  float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
  float m2 = m * m;
  return m2 * m2 * m;
}

QL_FN vec3 fresnelSchlick(vec3 f0, float cosTheta) {
  return f0 + (vec3(1.0f) - f0) * schlickWeight(cosTheta);
}

QL_FN float fresnelSchlickScalar(float f0, float cosTheta) {
  return f0 + (1.0f - f0) * schlickWeight(cosTheta);
}

// The dielectric layer's Schlick Fresnel at the micro-normal cosine cosOm. Seen from
// inside a solid (eta < 1) it is taken at the transmitted angle, and is 1 beyond the
// critical angle (total internal reflection).
QL_FN float dielectricFresnel(BsdfParams p, float cosOm) {
  if (p.eta > 0.0f && p.eta < 1.0f) {
    float sin2t = (1.0f - cosOm * cosOm) / (p.eta * p.eta);
    if (sin2t >= 1.0f) return 1.0f;
    cosOm = sqrt(1.0f - sin2t);
  }
  return fresnelSchlickScalar(dielectricF0(p), cosOm);
}

// Fresnel of the whole specular layer: the dielectric part weighted by
// `specular`, the metal part by metallic.
QL_FN vec3 specularFresnel(BsdfParams p, float cosTheta) {
  vec3 dielectric = vec3(p.specular * dielectricFresnel(p, cosTheta));
  return mix(dielectric, fresnelSchlick(p.baseColor, cosTheta), p.metallic);
}

// What the dielectric specular layer leaves to the diffuse base, at the
// half vector's cosine wo.h.
QL_FN float diffuseTransmission(BsdfParams p, float cosOm) {
  return 1.0f - p.specular * dielectricFresnel(p, cosOm);
}

// The mean of (1 - wo.h)^5 over cosine-distributed wi, as a function of
// wo.z: a cubic fitted to a 400x800 quadrature, within 1e-4 of it (0.028 at
// grazing, 8e-5 at normal incidence).
QL_FN float meanSchlickWeightOverCosine(float cosThetaO) {
  float mu = clamp(cosThetaO, 0.0f, 1.0f);
  return max(((-0.02568608f * mu + 0.07505259f) * mu - 0.07744563f) * mu + 0.0280687f, 0.0f);
}

// GGX normal distribution of a unit micro-normal m (m.z > 0).
QL_FN float ggxD(vec3 m, float alpha) {
  if (m.z <= 0.0f) return 0.0f;
  float tan2Scaled = (m.x * m.x + m.y * m.y) / (alpha * alpha);
  float denom = tan2Scaled + m.z * m.z;
  return 1.0f / (kPi * alpha * alpha * denom * denom);
}

// sqrt(z^2 + alpha^2 (x^2 + y^2)) = z * (1 + 2 Lambda(w)) for unit w, z > 0.
QL_FN float ggxLambdaTerm(vec3 w, float alpha) {
  return sqrt(w.z * w.z + alpha * alpha * (w.x * w.x + w.y * w.y));
}

// Smith masking of one direction: G1 = 1 / (1 + Lambda).
QL_FN float ggxG1(vec3 w, float alpha) {
  if (w.z <= 0.0f) return 0.0f;
  return 2.0f * w.z / (w.z + ggxLambdaTerm(w, alpha));
}

// Height-correlated G2 / (4 wo.z wi.z), the "visibility" term.
QL_FN float ggxVisibility(vec3 wo, vec3 wi, float alpha) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  return 0.5f / (ggxLambdaTerm(wo, alpha) * wi.z + ggxLambdaTerm(wi, alpha) * wo.z);
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals": a
// micro-normal m with density D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z.
QL_FN vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
  vec3 vh = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
  float lenSq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lenSq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) * inversesqrt(lenSq) : vec3(1.0f, 0.0f, 0.0f);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = kTwoPi * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrt(max(0.0f, 1.0f - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(0.0f, nh.z)));
}

QL_FN vec3 reflectAbout(vec3 wo, vec3 m) { return 2.0f * dot(wo, m) * m - wo; }

// Solid-angle density of wi = reflect(wo, m) with m from
// sampleGgxVisibleNormal: D_wo(m) / (4 wo.m) = D(m) / (2 (wo.z + term(wo))).
// Defined for every wi, also below the horizon, where such samples land
// before the caller rejects them; it integrates to 1 over the sphere.
QL_FN float ggxVndfReflectionPdf(vec3 wo, vec3 wi, float alpha) {
  vec3 h = wo + wi;
  float len2 = dot(h, h);
  if (wo.z <= 0.0f || !(len2 > 0.0f)) return 0.0f;
  vec3 m = h * inversesqrt(len2);
  return ggxD(m, alpha) / (2.0f * (wo.z + ggxLambdaTerm(wo, alpha)));
}

QL_FN vec3 lambertBrdf(vec3 albedo) { return albedo * kInvPi; }

// The half vector's cosine wo.h = wi.h for wi != -wo (then 0); the mean of
// the two keeps f(wo, wi) bit-for-bit symmetric.
QL_FN float halfVectorCosine(vec3 wo, vec3 wi) {
  vec3 h = wo + wi;
  float len2 = dot(h, h);
  return len2 > 0.0f ? max(0.5f * (dot(wo, h) + dot(wi, h)) * inversesqrt(len2), 0.0f) : 0.0f;
}

QL_FN vec3 bsdfEvalDiffuse(BsdfParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  return lambertBrdf(p.baseColor) * ((1.0f - p.metallic) * (1.0f - p.transmission) *
                                     diffuseTransmission(p, halfVectorCosine(wo, wi)));
}

QL_FN vec3 bsdfEvalSpecular(BsdfParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return vec3(0.0f);
  float alpha = ggxAlpha(p.roughness);
  vec3 m = normalize(wo + wi);
  // wo.m and wi.m are equal in exact arithmetic; averaging keeps f(wo, wi)
  // bit-for-bit symmetric.
  float cosOm = 0.5f * (dot(wo, m) + dot(wi, m));
  return specularFresnel(p, cosOm) * (ggxD(m, alpha) * ggxVisibility(wo, wi, alpha));
}

// The thin wall's far side: wi below the surface seen as its mirror image above.
QL_FN vec3 mirrorThroughSurface(vec3 w) { return vec3(w.x, w.y, -w.z); }

// Thin-walled transmission (wi.z < 0): what the dielectric layer lets through,
// tinted by the base colour, spread by the GGX lobe about the straight-through
// direction: (1 - metallic) t (1 - s Fd(wo.h')) baseColor D(h') V(wo, wi')
// with wi' the mirror image of wi.
QL_FN vec3 bsdfEvalTransmission(BsdfParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z >= 0.0f || p.transmission <= 0.0f) return vec3(0.0f);
  vec3 w = mirrorThroughSurface(wi);
  float alpha = ggxAlpha(p.roughness);
  vec3 m = normalize(wo + w);
  float through =
      (1.0f - p.metallic) * p.transmission * diffuseTransmission(p, halfVectorCosine(wo, w));
  return p.baseColor * (through * ggxD(m, alpha) * ggxVisibility(wo, w, alpha));
}

// Smith Lambda of one direction, either side.
QL_FN float ggxLambda(vec3 w, float alpha) {
  return 0.5f * (ggxLambdaTerm(w, alpha) / abs(w.z) - 1.0f);
}

// The micro-normal that refracts wo into wi (Walter et al. 2007), on wo's side; zero when
// wi cannot be a refraction of wo (the same side of the micro-surface).
QL_FN vec3 refractionHalfVector(vec3 wo, vec3 wi, float eta) {
  vec3 h = -(wo + eta * wi);
  float len2 = dot(h, h);
  if (!(len2 > 0.0f)) return vec3(0.0f);
  h *= inversesqrt(len2);
  if (h.z < 0.0f) h = -h;
  if (dot(wo, h) <= 0.0f || dot(wi, h) >= 0.0f) return vec3(0.0f);
  return h;
}

// Refraction into or out of a solid (wi.z < 0), Walter et al. 2007 for radiance:
// |wi.h| |wo.h| / (|wi.z| wo.z) (1 - s F) D(h) G2 / (eta wi.h + wo.h)^2, tinted by the base
// colour, for the transmitted share of the dielectric base.
QL_FN vec3 bsdfEvalRefraction(BsdfParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z >= 0.0f || p.transmission <= 0.0f) return vec3(0.0f);
  vec3 h = refractionHalfVector(wo, wi, p.eta);
  if (h.z <= 0.0f) return vec3(0.0f);
  float alpha = ggxAlpha(p.roughness);
  float oh = dot(wo, h), ih = dot(wi, h);
  float denom = p.eta * ih + oh;
  float g2 = 1.0f / (1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha));
  float value = abs(ih) * oh / (wo.z * abs(wi.z)) * diffuseTransmission(p, oh) * ggxD(h, alpha) *
                g2 / (denom * denom);
  return p.baseColor * ((1.0f - p.metallic) * p.transmission * value);
}

// Solid-angle density of wi = refract(wo, m) with m from sampleGgxVisibleNormal.
QL_FN float ggxVndfRefractionPdf(vec3 wo, vec3 wi, float eta, float alpha) {
  vec3 h = refractionHalfVector(wo, wi, eta);
  if (wo.z <= 0.0f || h.z <= 0.0f) return 0.0f;
  float oh = dot(wo, h), ih = dot(wi, h);
  float denom = eta * ih + oh;
  float visibleNormals = 2.0f * oh * ggxD(h, alpha) / (wo.z + ggxLambdaTerm(wo, alpha));
  return visibleNormals * eta * eta * abs(ih) / (denom * denom);
}

// f(wo, wi) without the cosine; below the surface only the transmission.
QL_FN vec3 bsdfEval(BsdfParams p, vec3 wo, vec3 wi) {
  if (!QL_BSDF_MICROFACET)
    return wo.z > 0.0f && wi.z > 0.0f ? lambertBrdf(p.baseColor) : vec3(0.0f);
  if (wi.z < 0.0f)
    return p.eta > 0.0f ? bsdfEvalRefraction(p, wo, wi) : bsdfEvalTransmission(p, wo, wi);
  return bsdfEvalDiffuse(p, wo, wi) + bsdfEvalSpecular(p, wo, wi);
}

// Directional albedo of the diffuse lobe: baseColor (1 - metallic) (1 - t)
// times the cosine-weighted mean of 1 - s Fd(wo.h), from the fitted mean of
// the Schlick weight (within 1e-4 of the exact integral).
QL_FN vec3 bsdfDiffuseAlbedo(BsdfParams p, float cosThetaO) {
  if (!QL_BSDF_MICROFACET) return p.baseColor;
  float meanFresnel =
      dielectricF0(p) + (1.0f - dielectricF0(p)) * meanSchlickWeightOverCosine(cosThetaO);
  return p.baseColor *
         ((1.0f - p.metallic) * (1.0f - p.transmission) * (1.0f - p.specular * meanFresnel));
}

// The lobes' sampling probabilities from their approximate albedos: specular
// (Fresnel at wo, ignoring shadowing), diffuse (the fit), transmission (what
// the dielectric layer passes at wo, ignoring shadowing).
struct BsdfLobes {
  float specular, diffuse, transmission;
};

QL_FN BsdfLobes bsdfLobeProbabilities(BsdfParams p, vec3 wo) {
  BsdfLobes l;
  if (!QL_BSDF_MICROFACET) {
    l.specular = 0.0f;
    l.diffuse = 1.0f;
    l.transmission = 0.0f;
    return l;
  }
  l.specular = luminance(specularFresnel(p, wo.z));
  l.diffuse = luminance(bsdfDiffuseAlbedo(p, wo.z));
  l.transmission =
      luminance(p.baseColor) * (1.0f - p.metallic) * p.transmission * diffuseTransmission(p, wo.z);
  float total = l.specular + l.diffuse + l.transmission;
  float scale = total > 0.0f ? 1.0f / total : 0.0f;
  l.specular *= scale;
  l.diffuse *= scale;
  l.transmission *= scale;
  return l;
}

QL_FN float bsdfSpecularProbability(BsdfParams p, vec3 wo) {
  return bsdfLobeProbabilities(p, wo).specular;
}

// The share of samples on the diffuse lobe (the part a learned distribution may replace).
QL_FN float bsdfDiffuseProbability(BsdfParams p, vec3 wo) {
  return bsdfLobeProbabilities(p, wo).diffuse;
}

// Solid-angle pdf of bsdfSample producing wi.
QL_FN float bsdfPdf(BsdfParams p, vec3 wo, vec3 wi) {
  if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
  if (!QL_BSDF_MICROFACET) return cosineHemispherePdf(wi.z);
  BsdfLobes l = bsdfLobeProbabilities(p, wo);
  float alpha = ggxAlpha(p.roughness);
  if (wi.z < 0.0f)
    return l.transmission * (p.eta > 0.0f
                                 ? ggxVndfRefractionPdf(wo, wi, p.eta, alpha)
                                 : ggxVndfReflectionPdf(wo, mirrorThroughSurface(wi), alpha));
  return l.specular * ggxVndfReflectionPdf(wo, wi, alpha) + l.diffuse * cosineHemispherePdf(wi.z);
}

// One-sample mixture of the lobes: u.z picks the lobe, u.xy the direction.
// Returns false (pdf = 0) when a microfacet lobe's sample leaves its side of
// the surface; that probability is part of the density, so the caller just
// ends or skips the path. pdf is the mixture density.
QL_FN bool bsdfSample(BsdfParams p, vec3 wo, vec3 u, QL_OUT(vec3) wi, QL_OUT(float) pdf) {
  if (!QL_BSDF_MICROFACET) {
    wi = sampleCosineHemisphere(vec2(u.x, u.y));
    pdf = wo.z > 0.0f ? cosineHemispherePdf(wi.z) : 0.0f;
    return pdf > 0.0f;
  }
  BsdfLobes l = bsdfLobeProbabilities(p, wo);
  float alpha = ggxAlpha(p.roughness);
  bool transmitted = false;
  if (u.z < l.specular + l.transmission) {
    vec3 m = sampleGgxVisibleNormal(wo, alpha, vec2(u.x, u.y));
    transmitted = u.z >= l.specular;
    if (transmitted && p.eta > 0.0f) {
      wi = refract(-wo, m, 1.0f / p.eta);  // zero under total internal reflection
      if (!(wi.z < 0.0f)) {
        pdf = 0.0f;
        return false;
      }
    } else {
      wi = reflectAbout(wo, m);
      if (wi.z <= 0.0f) {
        pdf = 0.0f;
        return false;
      }
      if (transmitted) wi = mirrorThroughSurface(wi);
    }
  } else {
    wi = sampleCosineHemisphere(vec2(u.x, u.y));
  }
  if (wo.z <= 0.0f || wi.z == 0.0f) {
    pdf = 0.0f;
    return false;
  }
  pdf = bsdfPdf(p, wo, wi);
  return pdf > 0.0f;
}

// bsdfSample plus the path throughput factor f * |cos| / pdf.
QL_FN bool bsdfSampleWeighted(BsdfParams p, vec3 wo, vec3 u, QL_OUT(vec3) wi, QL_OUT(float) pdf,
                              QL_OUT(vec3) weight) {
  weight = vec3(0.0f);
  if (!bsdfSample(p, wo, u, wi, pdf)) return false;
  weight = bsdfEval(p, wo, wi) * (abs(wi.z) / pdf);
  return true;
}

QL_END

#endif
