//! Per-state lighting constants, computed once when the lighting state changes.

use glam::{Vec3, Vec4};

use crate::state::light::{Light, MAX_LIGHTS};
use crate::state::light_model::LightModel;
use crate::state::material::{ColorMaterial, Material, MaterialMask};

/// One enabled light, in the form the equation uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedLight {
    pub ambient: Vec3,
    pub diffuse: Vec3,
    pub specular: Vec3,
    /// Whether the light has a position (w != 0) rather than a direction.
    pub positional: bool,
    /// Positional: the eye-space position divided by w. Directional: the unit direction to it.
    pub position: Vec3,
    /// For a directional light and an infinite viewer: the constant unit half vector.
    pub infinite_half: Vec3,
    /// Unit eye-space spot direction.
    pub spot_direction: Vec3,
    /// cos(cutoff), or `None` for the 180-degree cutoff (no spot).
    pub spot_cos_cutoff: Option<f32>,
    pub spot_exponent: f32,
    /// (constant, linear, quadratic), or `None` when attenuation is the identity (1, 0, 0).
    pub attenuation: Option<Vec3>,
}

impl PreparedLight {
    fn new(light: &Light) -> PreparedLight {
        let p = light.eye_position;
        let positional = p.w != 0.0;
        let position = if positional {
            p.truncate() / p.w
        } else {
            p.truncate().normalize_or_zero()
        };
        let attenuation = Vec3::new(
            light.constant_attenuation,
            light.linear_attenuation,
            light.quadratic_attenuation,
        );
        PreparedLight {
            ambient: light.ambient.truncate(),
            diffuse: light.diffuse.truncate(),
            specular: light.specular.truncate(),
            positional,
            position,
            infinite_half: (position + Vec3::Z).normalize_or_zero(),
            spot_direction: light.eye_spot_direction.normalize_or_zero(),
            spot_cos_cutoff: (light.spot_cutoff != 180.0)
                .then(|| (light.spot_cutoff as f64).to_radians().cos() as f32),
            spot_exponent: light.spot_exponent,
            attenuation: (positional && attenuation != Vec3::X).then_some(attenuation),
        }
    }

    /// att_i of §2.14.1 at `distance` from a positional light.
    pub fn attenuation_at(&self, distance: f32) -> f32 {
        match self.attenuation {
            Some(k) => 1.0 / (k.x + k.y * distance + k.z * distance * distance),
            None => 1.0,
        }
    }

    /// spot_i of §2.14.1 for the unit vector `to_light` from the vertex to the light.
    pub fn spot_factor(&self, to_light: Vec3) -> f32 {
        match self.spot_cos_cutoff {
            None => 1.0,
            Some(cos_cutoff) => {
                let cos_angle = (-to_light).dot(self.spot_direction);
                if cos_angle >= cos_cutoff {
                    cos_angle.max(0.0).powf(self.spot_exponent)
                } else {
                    0.0
                }
            }
        }
    }
}

/// One face's material and which of its properties follow the vertex color.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedFace {
    pub material: Material,
    pub tracked: MaterialMask,
    pub shininess: f32,
}

impl PreparedFace {
    /// The material with the color-material-tracked properties replaced by `color` (§2.14.3).
    pub fn material_for(&self, color: Vec4) -> Material {
        let mut material = self.material;
        if self.tracked != MaterialMask::NONE {
            material.set(self.tracked, color);
        }
        material
    }
}

/// Everything the equation needs, derived from the lighting state.
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedLighting {
    pub enabled: bool,
    lights: [Option<PreparedLight>; MAX_LIGHTS],
    light_count: usize,
    pub faces: [PreparedFace; 2],
    pub scene_ambient: Vec3,
    pub local_viewer: bool,
    pub two_side: bool,
    pub separate_specular: bool,
}

impl PreparedLighting {
    pub fn new(
        enabled: bool,
        lights: &[Light; MAX_LIGHTS],
        materials: &[Material; 2],
        model: &LightModel,
        color_material: &ColorMaterial,
    ) -> PreparedLighting {
        let mut prepared = [None; MAX_LIGHTS];
        let mut light_count = 0;
        for light in lights.iter().filter(|light| light.enabled) {
            prepared[light_count] = Some(PreparedLight::new(light));
            light_count += 1;
        }
        let tracked = color_material.tracked();
        let face = |i: usize| PreparedFace {
            material: materials[i],
            tracked: tracked[i],
            shininess: materials[i].shininess,
        };
        PreparedLighting {
            enabled,
            lights: prepared,
            light_count,
            faces: [face(0), face(1)],
            scene_ambient: model.ambient.truncate(),
            local_viewer: model.local_viewer,
            two_side: model.two_side,
            separate_specular: model.separate_specular(),
        }
    }

    /// The enabled lights, in order.
    pub fn lights(&self) -> impl Iterator<Item = &PreparedLight> {
        self.lights[..self.light_count].iter().flatten()
    }
}
