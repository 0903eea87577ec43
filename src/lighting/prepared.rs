//! Per-state lighting constants, computed once when the lighting state changes.

use glam::{DVec3, Vec4};

use crate::state::light::{Light, MAX_LIGHTS};
use crate::state::light_model::LightModel;
use crate::state::material::{ColorMaterial, Material, MaterialMask};

/// One enabled light, in the form the equation uses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedLight {
    /// The light's GL_AMBIENT color a_cli, RGB.
    pub ambient: DVec3,
    /// The light's GL_DIFFUSE color d_cli, RGB.
    pub diffuse: DVec3,
    /// The light's GL_SPECULAR color s_cli, RGB.
    pub specular: DVec3,
    /// Whether the light has a position (w != 0) rather than a direction.
    pub positional: bool,
    /// Positional: the eye-space position divided by w. Directional: the unit direction to it.
    pub position: DVec3,
    /// For a directional light and an infinite viewer: the constant unit half vector.
    pub infinite_half: DVec3,
    /// Unit eye-space spot direction.
    pub spot_direction: DVec3,
    /// cos(cutoff), or `None` for the 180-degree cutoff (no spot).
    pub spot_cos_cutoff: Option<f64>,
    /// GL_SPOT_EXPONENT s_rli.
    pub spot_exponent: f64,
    /// (constant, linear, quadratic), or `None` when attenuation is the identity (1, 0, 0).
    pub attenuation: Option<DVec3>,
}

impl PreparedLight {
    fn new(light: &Light) -> PreparedLight {
        let p = light.eye_position.as_dvec4();
        let positional = p.w != 0.0;
        let position = if positional {
            p.truncate() / p.w
        } else {
            p.truncate().normalize_or_zero()
        };
        let attenuation = DVec3::new(
            light.constant_attenuation.into(),
            light.linear_attenuation.into(),
            light.quadratic_attenuation.into(),
        );
        let rgb = |c: Vec4| c.truncate().as_dvec3();
        PreparedLight {
            ambient: rgb(light.ambient),
            diffuse: rgb(light.diffuse),
            specular: rgb(light.specular),
            positional,
            position,
            infinite_half: (position + DVec3::Z).normalize_or_zero(),
            spot_direction: light.eye_spot_direction.as_dvec3().normalize_or_zero(),
            spot_cos_cutoff: (light.spot_cutoff != 180.0)
                .then(|| f64::from(light.spot_cutoff).to_radians().cos()),
            spot_exponent: light.spot_exponent.into(),
            attenuation: (positional && attenuation != DVec3::X).then_some(attenuation),
        }
    }

    /// att_i of §2.14.1 at `distance` from a positional light.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::Vec4;
    /// let mut lights = std::array::from_fn(Light::initial);
    /// lights[0].enabled = true;
    /// lights[0].eye_position = Vec4::new(0.0, 0.0, 0.0, 1.0); // positional
    /// lights[0].linear_attenuation = 0.5;
    /// let lighting = PreparedLighting::new(
    ///     true,
    ///     &lights,
    ///     &[Material::default(); 2],
    ///     &LightModel::default(),
    ///     &ColorMaterial::default(),
    /// );
    /// let light = lighting.lights().next().unwrap();
    /// assert_eq!(light.attenuation_at(2.0), 1.0 / (1.0 + 0.5 * 2.0));
    /// ```
    pub fn attenuation_at(&self, distance: f64) -> f64 {
        match self.attenuation {
            Some(k) => 1.0 / (k.x + k.y * distance + k.z * distance * distance),
            None => 1.0,
        }
    }

    /// spot_i of §2.14.1 for the unit vector `to_light` from the vertex to the light.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::PreparedLighting;
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::{DVec3, Vec4};
    /// // A spot at the origin pointing down -z (the initial direction), 30-degree cutoff.
    /// let mut lights = std::array::from_fn(Light::initial);
    /// lights[0].enabled = true;
    /// lights[0].eye_position = Vec4::new(0.0, 0.0, 0.0, 1.0);
    /// lights[0].spot_cutoff = 30.0;
    /// let lighting = PreparedLighting::new(
    ///     true,
    ///     &lights,
    ///     &[Material::default(); 2],
    ///     &LightModel::default(),
    ///     &ColorMaterial::default(),
    /// );
    /// let spot = lighting.lights().next().unwrap();
    /// assert_eq!(spot.spot_factor(DVec3::Z), 1.0); // vertex on the axis, below the light
    /// assert_eq!(spot.spot_factor(DVec3::X), 0.0); // 90 degrees off: outside the cone
    /// ```
    pub fn spot_factor(&self, to_light: DVec3) -> f64 {
        match self.spot_cos_cutoff {
            None => 1.0,
            Some(cos_cutoff) => {
                let cos_angle = (-to_light).dot(self.spot_direction);
                if cos_angle >= cos_cutoff {
                    super::power(cos_angle.max(0.0), self.spot_exponent)
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
    /// The face's material as set by glMaterial.
    pub material: Material,
    /// The properties that color material replaces with the current color (§2.14.3).
    pub tracked: MaterialMask,
    /// GL_SHININESS s_rm, in double precision.
    pub shininess: f64,
}

impl PreparedFace {
    /// The material with the color-material-tracked properties replaced by `color` (§2.14.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::lighting::PreparedFace;
    /// use fflight::state::material::{Material, MaterialMask};
    /// use glam::Vec4;
    /// let face = PreparedFace {
    ///     material: Material::default(),
    ///     tracked: MaterialMask::DIFFUSE,
    ///     shininess: 0.0,
    /// };
    /// let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    /// assert_eq!(face.material_for(red).diffuse, red);
    /// assert_eq!(face.material_for(red).ambient, Material::default().ambient);
    /// ```
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
    /// GL_LIGHTING: when false, vertices keep their current colors.
    pub enabled: bool,
    lights: [Option<PreparedLight>; MAX_LIGHTS],
    light_count: usize,
    /// The front (0) and back (1) materials.
    pub faces: [PreparedFace; 2],
    /// GL_LIGHT_MODEL_AMBIENT a_cs, RGB.
    pub scene_ambient: DVec3,
    /// GL_LIGHT_MODEL_LOCAL_VIEWER v_bs: the eye at the origin, not at infinity along +z.
    pub local_viewer: bool,
    /// GL_LIGHT_MODEL_TWO_SIDE t_bs: back faces get their own colors.
    pub two_side: bool,
    /// GL_LIGHT_MODEL_COLOR_CONTROL is GL_SEPARATE_SPECULAR_COLOR c_es.
    pub separate_specular: bool,
}

impl PreparedLighting {
    /// Prepares the constants of §2.14.1 from the lighting state: the enabled lights in order
    /// (positions homogenized, cutoff cosines, half vectors for infinite lights), the materials
    /// with the properties color material tracks, and the light model.
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
    /// assert!(lighting.enabled);
    /// assert_eq!(lighting.lights().count(), 1);
    /// assert!(!lighting.two_side);
    /// ```
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
            shininess: materials[i].shininess.into(),
        };
        PreparedLighting {
            enabled,
            lights: prepared,
            light_count,
            faces: [face(0), face(1)],
            scene_ambient: model.ambient.truncate().as_dvec3(),
            local_viewer: model.local_viewer,
            two_side: model.two_side,
            separate_specular: model.separate_specular(),
        }
    }

    /// The enabled lights, in order.
    ///
    /// # Examples
    ///
    /// ```
    /// # use fflight::lighting::{PreparedLighting, VertexInput};
    /// # use fflight::state::{light::Light, light_model::LightModel};
    /// # use fflight::state::material::{ColorMaterial, Material};
    /// # use glam::{DVec3, DVec4, Vec4};
    /// // Lights 2 and 5 enabled; the initial materials.
    /// let mut lights = std::array::from_fn(Light::initial);
    /// lights[2].enabled = true;
    /// lights[5].enabled = true;
    /// let lighting = PreparedLighting::new(
    ///     true,
    ///     &lights,
    ///     &[Material::default(); 2],
    ///     &LightModel::default(),
    ///     &ColorMaterial::default(),
    /// );
    /// assert_eq!(lighting.lights().count(), 2);
    /// // Light 2 is black as initialized; positions become unit directions (w = 0).
    /// assert_eq!(lighting.lights().next().unwrap().diffuse, DVec3::ZERO);
    /// assert!(lighting.lights().all(|light| light.position == DVec3::Z));
    /// ```
    pub fn lights(&self) -> impl Iterator<Item = &PreparedLight> {
        self.lights[..self.light_count].iter().flatten()
    }
}
