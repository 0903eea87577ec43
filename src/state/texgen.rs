//! Texture coordinate generation (§2.11.4): per texture unit, a mode, an object plane and an
//! eye plane for each of s, t, r and q, and their enables; and the generation itself.

use glam::{DMat4, DVec3, DVec4, Vec4};

use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::lighting::homogenize;

/// One coordinate's generation state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoordGen {
    /// GL_TEXTURE_GEN_S (or _T, _R, _Q) enabled.
    pub enabled: bool,
    /// GL_TEXTURE_GEN_MODE.
    pub mode: GLenum,
    /// GL_OBJECT_PLANE.
    pub object_plane: Vec4,
    /// In eye coordinates: the plane given, times the inverse of the modelview matrix
    /// current when it was given.
    pub eye_plane: Vec4,
}

/// The generation state of a texture unit, for s, t, r and q.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGen {
    /// s, t, r and q.
    pub coords: [CoordGen; 4],
}

impl Default for TexGen {
    /// Every mode GL_EYE_LINEAR; the planes of s and t select x and y, those of r and q are 0.
    fn default() -> TexGen {
        let plane = |i: usize| match i {
            0 => Vec4::X,
            1 => Vec4::Y,
            _ => Vec4::ZERO,
        };
        TexGen {
            coords: std::array::from_fn(|i| CoordGen {
                enabled: false,
                mode: GL_EYE_LINEAR,
                object_plane: plane(i),
                eye_plane: plane(i),
            }),
        }
    }
}

/// The index (s 0 to q 3) of glTexGen's `coord`.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texgen::coord_index};
/// assert_eq!(coord_index(GL_R), Ok(2));
/// assert!(coord_index(GL_TEXTURE_GEN_S).is_err());
/// ```
pub fn coord_index(coord: GLenum) -> GlResult<usize> {
    match coord {
        GL_S..=GL_Q => Ok((coord - GL_S) as usize),
        _ => Err(GlError::InvalidEnum),
    }
}

/// How many values glTexGen's `pname` takes (0 for a bad pname: the command rejects it).
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::texgen::tex_gen_param_count};
/// assert_eq!((tex_gen_param_count(GL_EYE_PLANE), tex_gen_param_count(GL_TEXTURE_GEN_MODE)), (4, 1));
/// ```
pub fn tex_gen_param_count(pname: GLenum) -> usize {
    match pname {
        GL_TEXTURE_GEN_MODE => 1,
        GL_OBJECT_PLANE | GL_EYE_PLANE => 4,
        _ => 0,
    }
}

impl TexGen {
    /// glTexGen{ifd}v (§2.11.4) for coordinate `coord` (0 to 3): Mesa's order of checks, the
    /// pname, then the mode (GL_SPHERE_MAP for s and t only, GL_NORMAL_MAP and
    /// GL_REFLECTION_MAP not for q). `modelview` turns an eye plane into eye coordinates.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texgen::TexGen};
    /// use glam::DMat4;
    /// let mut generation = TexGen::default();
    /// let modelview = DMat4::from_translation(glam::DVec3::new(0.0, 0.0, -1.0));
    /// generation.set(0, GL_EYE_PLANE, &[0.0, 0.0, 1.0, 0.0], &modelview)?;
    /// // The plane times the inverse modelview: z >= -1 becomes z + 1 >= 0.
    /// assert_eq!(generation.get(0, GL_EYE_PLANE)?, [0.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn set(
        &mut self,
        coord: usize,
        pname: GLenum,
        params: &[f64],
        modelview: &DMat4,
    ) -> GlResult {
        let coord_gen = &mut self.coords[coord];
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let &[value] = params else {
                    return Err(GlError::InvalidValue);
                };
                let mode = value as GLenum;
                let allowed = match mode {
                    GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
                    GL_SPHERE_MAP => coord < 2,
                    GL_NORMAL_MAP | GL_REFLECTION_MAP => coord < 3,
                    _ => false,
                };
                // An integer that names no mode (2.5 is not GL_SPHERE_MAP either).
                if !allowed || f64::from(mode) != value {
                    return Err(GlError::InvalidEnum);
                }
                coord_gen.mode = mode;
            }
            GL_OBJECT_PLANE | GL_EYE_PLANE => {
                let plane: [f64; 4] = params.try_into().map_err(|_| GlError::InvalidValue)?;
                let plane = DVec4::from_array(plane);
                if pname == GL_OBJECT_PLANE {
                    coord_gen.object_plane = plane.as_vec4();
                } else {
                    // (p1 p2 p3 p4) M^-1 as a row vector: the inverse's transpose times it.
                    coord_gen.eye_plane = (modelview.inverse().transpose() * plane).as_vec4();
                }
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetTexGen{ifd}v: the mode, or a plane (the eye plane in eye coordinates).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, state::texgen::TexGen};
    /// assert_eq!(TexGen::default().get(3, GL_TEXTURE_GEN_MODE)?, [GL_EYE_LINEAR as f64]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get(&self, coord: usize, pname: GLenum) -> GlResult<Vec<f64>> {
        let coord_gen = &self.coords[coord];
        let plane = |p: Vec4| p.as_dvec4().to_array().to_vec();
        match pname {
            GL_TEXTURE_GEN_MODE => Ok(vec![f64::from(coord_gen.mode)]),
            GL_OBJECT_PLANE => Ok(plane(coord_gen.object_plane)),
            GL_EYE_PLANE => Ok(plane(coord_gen.eye_plane)),
            _ => Err(GlError::InvalidEnum),
        }
    }

    /// The generation a vertex needs, or None when no coordinate is generated.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texgen::TexGen;
    /// let mut generation = TexGen::default();
    /// assert!(generation.prepared().is_none()); // nothing enabled
    /// generation.coords[0].enabled = true;
    /// assert!(generation.prepared().is_some_and(|p| p.coords[0].is_some() && p.coords[1].is_none()));
    /// ```
    pub fn prepared(&self) -> Option<PreparedTexGen> {
        self.coords
            .iter()
            .any(|c| c.enabled)
            .then(|| PreparedTexGen {
                coords: self.coords.map(|c| {
                    c.enabled.then_some(match c.mode {
                        GL_OBJECT_LINEAR => Generation::ObjectLinear(c.object_plane.as_dvec4()),
                        GL_EYE_LINEAR => Generation::EyeLinear(c.eye_plane.as_dvec4()),
                        GL_SPHERE_MAP => Generation::SphereMap,
                        GL_REFLECTION_MAP => Generation::ReflectionMap,
                        _ => Generation::NormalMap,
                    })
                }),
            })
    }
}

/// One enabled coordinate's function.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Generation {
    /// GL_OBJECT_LINEAR with its plane.
    ObjectLinear(DVec4),
    /// GL_EYE_LINEAR with its plane in eye coordinates.
    EyeLinear(DVec4),
    /// GL_SPHERE_MAP.
    SphereMap,
    /// GL_REFLECTION_MAP.
    ReflectionMap,
    /// GL_NORMAL_MAP.
    NormalMap,
}

/// The enabled coordinates' functions (None: the coordinate is taken from the current
/// texture coordinates).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedTexGen {
    /// s, t, r and q.
    pub coords: [Option<Generation>; 4],
}

/// What generation reads of a vertex: its object and eye coordinates and its eye-space
/// normal (after rescaling and normalization, §2.11.3).
#[derive(Clone, Copy, Debug)]
pub struct GenInput {
    /// Object coordinates.
    pub object: DVec4,
    /// Eye coordinates.
    pub eye: DVec4,
    /// The eye-space normal.
    pub normal: DVec3,
}

impl PreparedTexGen {
    /// The texture coordinates of a vertex whose current ones are `current` (§2.11.4), in
    /// double precision.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::state::texgen::{GenInput, TexGen};
    /// use glam::{DVec3, DVec4, Vec4};
    /// let mut generation = TexGen::default();
    /// // Initially GL_EYE_LINEAR with s's eye plane (1, 0, 0, 0): s = eye x.
    /// generation.coords[0].enabled = true;
    /// let prepared = generation.prepared().unwrap();
    /// let eye = DVec4::new(0.25, 0.0, 0.0, 1.0);
    /// let input = GenInput { object: DVec4::W, eye, normal: DVec3::Z };
    /// assert_eq!(prepared.generate(&input, Vec4::new(9.0, 8.0, 7.0, 1.0)), Vec4::new(0.25, 8.0, 7.0, 1.0));
    /// ```
    pub fn generate(&self, input: &GenInput, current: Vec4) -> Vec4 {
        let mut reflection = None;
        let mut reflect = || {
            *reflection.get_or_insert_with(|| {
                // u: the unit vector from the eye to the vertex; r = u - 2 n (n . u).
                let u = homogenize(input.eye).normalize_or_zero();
                let n = input.normal;
                u - 2.0 * n * n.dot(u)
            })
        };
        let mut out = current.to_array();
        for (k, generation) in self.coords.iter().enumerate() {
            let Some(generation) = generation else {
                continue;
            };
            let value = match *generation {
                Generation::ObjectLinear(plane) => plane.dot(input.object),
                Generation::EyeLinear(plane) => plane.dot(input.eye),
                Generation::SphereMap => {
                    let r = reflect();
                    let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
                    r[k] / m + 0.5
                }
                Generation::ReflectionMap => reflect()[k],
                Generation::NormalMap => input.normal[k],
            };
            out[k] = value as f32;
        }
        Vec4::from_array(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn modes_are_checked_per_coordinate() {
        let mut tex_gen = TexGen::default();
        let identity = DMat4::IDENTITY;
        let mode = |m: GLenum| [f64::from(m)];
        assert!(
            tex_gen
                .set(0, GL_TEXTURE_GEN_MODE, &mode(GL_SPHERE_MAP), &identity)
                .is_ok()
        );
        assert_eq!(
            tex_gen.set(2, GL_TEXTURE_GEN_MODE, &mode(GL_SPHERE_MAP), &identity),
            Err(GlError::InvalidEnum)
        );
        assert!(
            tex_gen
                .set(2, GL_TEXTURE_GEN_MODE, &mode(GL_NORMAL_MAP), &identity)
                .is_ok()
        );
        assert_eq!(
            tex_gen.set(3, GL_TEXTURE_GEN_MODE, &mode(GL_REFLECTION_MAP), &identity),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(
            tex_gen.set(
                3,
                GL_TEXTURE_GEN_MODE,
                &[f64::from(GL_EYE_LINEAR) + 0.5],
                &identity
            ),
            Err(GlError::InvalidEnum)
        );
        assert_eq!(tex_gen.coords[3].mode, GL_EYE_LINEAR);
    }
}
