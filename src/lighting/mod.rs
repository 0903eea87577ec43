//! The lighting equation of §2.14.1, evaluated per vertex from constants prepared once per
//! state change.
//!
//! The equation's per-light sum is regrouped by material factor:
//! `Σ att·spot·(a_m·a_l + (n⊙L)·d_m·d_l + f·(n⊙h)^s·s_m·s_l)
//!  = a_m·Σ att·spot·a_l + d_m·Σ att·spot·(n⊙L)·d_l + s_m·Σ att·spot·f·(n⊙h)^s·s_l`,
//! so the material, which color material may replace per vertex, multiplies three sums once
//! instead of entering every light's products.
//!
//! The evaluation runs in double precision from the single-precision state: high specular
//! and spot exponents magnify rounding (x^128 multiplies a relative error by 128), and this
//! path is the reference a faster single-precision engine is measured against.

pub mod batch;
pub mod fast;
pub mod lanes;
mod prepared;

pub use prepared::{PreparedFace, PreparedLight, PreparedLighting};

use glam::{DVec3, DVec4, Vec4};

/// The colors lighting gives one face of a vertex (§2.14.1): primary and secondary, clamped.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FaceColors {
    /// The primary color c_pri: lit, with the specular term unless the color control
    /// separates it; unlit, the current color.
    pub primary: Vec4,
    /// The secondary color c_sec: lit, the specular term with GL_SEPARATE_SPECULAR_COLOR, else
    /// zero, alpha 0; unlit, the current secondary color.
    pub secondary: Vec4,
}

/// The colors of a vertex for both faces. Without two-sided lighting the back colors equal the
/// front ones (§2.14.1: the front colors are used for every polygon).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LitVertex {
    /// The colors of front-facing primitives.
    pub front: FaceColors,
    /// The colors of back-facing primitives (lit with the negated normal and the back material
    /// under two-sided lighting).
    pub back: FaceColors,
}

/// What the equation reads of one vertex: eye-space position, eye-space normal (already
/// rescaled or normalized as enabled), and the current colors.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexInput {
    /// The vertex in eye coordinates, homogeneous (V of §2.14.1).
    pub eye: DVec4,
    /// The eye-space normal n.
    pub normal: DVec3,
    /// The current color: passed through when lighting is off, or the material properties
    /// that color material tracks (§2.14.3).
    pub color: Vec4,
    /// The current secondary color, passed through when lighting is off.
    pub secondary_color: Vec4,
}

/// Clamps each component to [0, 1] (§2.14.8). A NaN component, whose result GL leaves
/// unspecified (§2.1.1), becomes 0 on every target: glam's `clamp` gives 0 with SSE2 and in its
/// scalar code but keeps NaN with NEON, whose max propagates it.
pub(crate) fn clamp01(c: Vec4) -> Vec4 {
    Vec4::select(c.cmpgt(Vec4::ZERO), c.min(Vec4::ONE), Vec4::ZERO)
}

/// The per-face sums of light colors, weighted by the light-dependent factors.
#[derive(Clone, Copy, Default)]
struct LightSums {
    ambient: DVec3,
    diffuse: [DVec3; 2],
    specular: [DVec3; 2],
}

impl PreparedLighting {
    /// Lights one vertex (§2.14.1), or passes its current colors through when lighting is off.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::{PreparedLighting, VertexInput};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::{DVec3, DVec4, Vec4};
    /// // Light 0 as initialized (white, from +z), enabled; the initial materials.
    /// let mut lights = std::array::from_fn(Light::initial);
    /// lights[0].enabled = true;
    /// let lighting = PreparedLighting::new(
    ///     true,
    ///     &lights,
    ///     &[Material::default(); 2],
    ///     &LightModel::default(),
    ///     &ColorMaterial::default(),
    /// );
    /// let lit = lighting.shade(&VertexInput {
    ///     eye: DVec4::new(0.0, 0.0, -5.0, 1.0),
    ///     normal: DVec3::Z,
    ///     color: Vec4::ONE,
    ///     secondary_color: Vec4::ZERO,
    /// });
    /// // emission 0 + ambient 0.2 * scene ambient 0.2 + diffuse 0.8 * (n.L = 1) * 1.
    /// assert!((lit.front.primary.x - 0.84).abs() < 1e-6);
    /// assert_eq!(lit.front.primary.w, 1.0); // the diffuse material's alpha
    /// assert_eq!(lit.back, lit.front); // one-sided lighting
    /// ```
    pub fn shade(&self, input: &VertexInput) -> LitVertex {
        if !self.enabled {
            let face = FaceColors {
                primary: clamp01(input.color),
                secondary: clamp01(input.secondary_color),
            };
            return LitVertex {
                front: face,
                back: face,
            };
        }
        let position = homogenize(input.eye);
        let sums = self.light_sums(position, input.normal);
        let front = self.face_color(0, &sums, input.color);
        let back = if self.two_side {
            self.face_color(1, &sums, input.color)
        } else {
            front
        };
        LitVertex { front, back }
    }

    fn light_sums(&self, position: DVec3, normal: DVec3) -> LightSums {
        let mut sums = LightSums::default();
        let eye_direction = if self.local_viewer {
            (-position).normalize_or_zero()
        } else {
            DVec3::Z
        };
        for light in self.lights() {
            let (to_light, attenuation) = if light.positional {
                let offset = light.position - position;
                let distance = offset.length();
                // One division, not three (the batch engine does the same).
                let to_light = offset * (1.0 / distance);
                (to_light, light.attenuation_at(distance))
            } else {
                (light.position, 1.0)
            };
            let spot = light.spot_factor(to_light);
            if spot == 0.0 {
                continue;
            }
            let weight = attenuation * spot;
            sums.ambient += weight * light.ambient;

            let half = if light.positional || self.local_viewer {
                (to_light + eye_direction).normalize_or_zero()
            } else {
                light.infinite_half
            };
            let n_dot_l = normal.dot(to_light);
            let n_dot_h = normal.dot(half);
            // The back face sees the negated normal (§2.14.1).
            let faces = if self.two_side { 2 } else { 1 };
            for (face, sign) in [1.0f64, -1.0].into_iter().enumerate().take(faces) {
                let diffuse = (sign * n_dot_l).max(0.0);
                if diffuse > 0.0 {
                    sums.diffuse[face] += (weight * diffuse) * light.diffuse;
                    let shininess = self.faces[face].shininess;
                    let specular = power((sign * n_dot_h).max(0.0), shininess);
                    sums.specular[face] += (weight * specular) * light.specular;
                }
            }
        }
        sums
    }

    fn face_color(&self, face: usize, sums: &LightSums, color: Vec4) -> FaceColors {
        let material = self.faces[face].material_for(color);
        let rgb = |c: Vec4| c.truncate().as_dvec3();
        let ambient = rgb(material.ambient);
        let unlit = rgb(material.emission) + ambient * (self.scene_ambient + sums.ambient);
        let diffuse = rgb(material.diffuse) * sums.diffuse[face];
        let specular = rgb(material.specular) * sums.specular[face];
        let color = |c: DVec3, alpha: f32| clamp01(c.as_vec3().extend(alpha));
        let alpha = material.diffuse.w;
        if self.separate_specular {
            FaceColors {
                primary: color(unlit + diffuse, alpha),
                secondary: color(specular, 0.0),
            }
        } else {
            FaceColors {
                primary: color(unlit + diffuse + specular, alpha),
                secondary: Vec4::ZERO,
            }
        }
    }
}

/// `base` to the power `exponent` (a shininess or spot exponent, in [0, 128]). Integer
/// exponents, the common case, take repeated multiplication: exact to a few ulps and several
/// times faster than the general power. 0^0 is 1, as the equation needs.
pub(crate) fn power(base: f64, exponent: f64) -> f64 {
    if exponent.fract() == 0.0 {
        base.powi(exponent as i32)
    } else {
        base.powf(exponent)
    }
}

/// A homogeneous eye-space point as a 3D point (§2.14.1 treats V as homogeneous).
pub(crate) fn homogenize(eye: DVec4) -> DVec3 {
    if eye.w != 0.0 && eye.w != 1.0 {
        eye.truncate() / eye.w
    } else {
        eye.truncate()
    }
}

#[cfg(test)]
mod tests {
    use super::power;

    #[test]
    fn integer_powers_agree_with_the_general_power() {
        for exponent in 0..=128 {
            for base in [0.0, 0.3, 0.9, 0.999, 1.0, 1.02] {
                let e = f64::from(exponent);
                let (fast, general) = (power(base, e), base.powf(e));
                assert!(
                    (fast - general).abs() <= 1e-14 * general.abs().max(1.0),
                    "{base}^{e}: {fast} vs {general}"
                );
            }
        }
        assert_eq!(power(0.0, 0.0), 1.0);
        assert_eq!(power(0.25, 0.5), 0.5);
    }
}
