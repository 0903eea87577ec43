//! Texturing commands (§3.8, §2.7 glActiveTexture, §6.1.3-6.1.4 queries). Every command is
//! GL_INVALID_OPERATION between glBegin and glEnd and changes nothing on an error. Nothing is
//! ever sampled: there is no rasterizer.

use std::sync::Arc;

use super::query::{StateValue, enumeration, int};
use crate::context::Context;
use crate::error::{GlError, GlResult};
use crate::gl::*;
use crate::state::convert::{color_to_int, float_to_int, int_params};
use crate::state::texture::{
    MAX_TEXTURE_LOD_BIAS, MAX_TEXTURE_UNITS, Target, TextureObject, tex_env_count,
    tex_parameter_count,
};
use crate::state::texture_image::{
    Base, Layout, PixelFormat, TexImage, internal_format, pack, transfer, unpack,
};

/// Where an image command's target puts the image: the texture target, the cube map face
/// (0 otherwise), and whether it is a proxy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageTarget {
    /// The texture target (1D, 2D, 3D or cube map).
    pub target: Target,
    /// The cube map face, 0 to 5 (0 for other targets).
    pub face: usize,
    /// A GL_PROXY_* target: checked, never stored.
    pub proxy: bool,
}

impl ImageTarget {
    /// The image target `target` names for a command on `dimensions`-dimensional images:
    /// GL_INVALID_ENUM for any other (`proxies`: whether the command takes proxy targets).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::ImageTarget, gl::*, state::texture::Target, GlError};
    /// let target = ImageTarget::of(GL_TEXTURE_CUBE_MAP_NEGATIVE_X, 2, false)?;
    /// assert_eq!((target.target, target.face, target.proxy), (Target::CubeMap, 1, false));
    /// assert!(ImageTarget::of(GL_PROXY_TEXTURE_2D, 2, true)?.proxy);
    /// assert_eq!(ImageTarget::of(GL_TEXTURE_3D, 2, true).err(), Some(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn of(target: GLenum, dimensions: usize, proxies: bool) -> GlResult<ImageTarget> {
        let faces = GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
        let image = if faces.contains(&target) {
            ImageTarget {
                target: Target::CubeMap,
                face: (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize,
                proxy: false,
            }
        } else if let Some(kind) = Target::ALL.into_iter().find(|t| t.proxy() == target) {
            ImageTarget {
                target: kind,
                face: 0,
                proxy: true,
            }
        } else {
            match Target::of(target) {
                // GL_TEXTURE_CUBE_MAP itself names no image.
                Some(kind) if kind != Target::CubeMap => ImageTarget {
                    target: kind,
                    face: 0,
                    proxy: false,
                },
                _ => return Err(GlError::InvalidEnum),
            }
        };
        if image.target.dimensions() != dimensions || (image.proxy && !proxies) {
            return Err(GlError::InvalidEnum);
        }
        Ok(image)
    }

    /// Like `of`, for every dimension (glGetTexLevelParameter, glGetTexImage).
    fn any(target: GLenum, proxies: bool) -> GlResult<ImageTarget> {
        (1..=3)
            .find_map(|d| ImageTarget::of(target, d, proxies).ok())
            .ok_or(GlError::InvalidEnum)
    }

    fn check_level(&self, level: GLint) -> GlResult<usize> {
        match usize::try_from(level) {
            Ok(level) if level < self.target.levels() => Ok(level),
            _ => Err(GlError::InvalidValue),
        }
    }
}

/// Whether `size` (with its border) is a legal image size of GL 1.5 (§3.8.1): 2^n + 2 border,
/// at most the target's maximum (0 is legal: an empty image).
fn legal_size(size: i32, border: i32, max: i32) -> bool {
    let inner = size - 2 * border;
    size == 0 || (inner >= 0 && inner <= max && (inner as u32).is_power_of_two())
}

/// The size of an image of a `dimensions`-dimensional target: unused sizes are 1.
fn image_size(dimensions: usize, size: [GLsizei; 3]) -> [GLsizei; 3] {
    std::array::from_fn(|i| if i < dimensions { size[i] } else { 1 })
}

/// The arguments of glTexImage1D/2D/3D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexImageArgs {
    /// `target`, as given.
    pub target: GLenum,
    /// The mipmap level.
    pub level: GLint,
    /// The requested internal format (a base format, a sized one, or 1 to 4).
    pub internal_format: GLint,
    /// Width, height, depth; the unused ones ignored.
    pub size: [GLsizei; 3],
    /// The border width, 0 or 1.
    pub border: GLint,
    /// The format of the client pixels.
    pub format: GLenum,
    /// The type of the client pixels.
    pub ty: GLenum,
}

/// The arguments of glTexSubImage1D/2D/3D and glCopyTexSubImage (format and type unused).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SubImageArgs {
    /// `target`, as given.
    pub target: GLenum,
    /// The mipmap level.
    pub level: GLint,
    /// x, y, z offset of the region in the image; the unused ones ignored.
    pub offset: [GLint; 3],
    /// Width, height, depth of the region; the unused ones ignored.
    pub size: [GLsizei; 3],
    /// The format of the client pixels.
    pub format: GLenum,
    /// The type of the client pixels.
    pub ty: GLenum,
}

impl Context {
    /// glActiveTexture (§2.7).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.active_texture(GL_TEXTURE3)?;
    /// assert_eq!(ctx.get(GL_ACTIVE_TEXTURE)?.as_ints(), [GL_TEXTURE3 as i32]);
    /// assert_eq!(ctx.active_texture(GL_TEXTURE0 + 8), Err(GlError::InvalidEnum)); // 8 units
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn active_texture(&mut self, texture: GLenum) -> GlResult {
        self.outside_begin_end()?;
        self.textures.set_active(texture)
    }

    /// glGenTextures: writes `n` unused names into `names`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// let mut names = [0; 3];
    /// ctx.gen_textures(3, &mut names)?;
    /// assert!(names.iter().all(|&n| n != 0));
    /// assert_eq!(ctx.is_texture(names[0])?, GL_FALSE); // a texture once bound
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn gen_textures(&mut self, n: GLsizei, names: &mut [GLuint]) -> GlResult {
        self.outside_begin_end()?;
        let count = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        let names = names.get_mut(..count).ok_or(GlError::InvalidValue)?;
        let generated = self.textures.generate(count);
        if generated.len() < count {
            return Err(GlError::OutOfMemory);
        }
        names.copy_from_slice(&generated);
        Ok(())
    }

    /// glDeleteTextures (§3.8.12): the bindings of deleted objects revert to 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_texture(GL_TEXTURE_2D, 7)?;
    /// ctx.delete_textures(1, &[7])?;
    /// assert_eq!(ctx.get(GL_TEXTURE_BINDING_2D)?.as_ints(), [0]);
    /// assert_eq!(ctx.is_texture(7)?, GL_FALSE);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn delete_textures(&mut self, n: GLsizei, names: &[GLuint]) -> GlResult {
        self.outside_begin_end()?;
        let count = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        let names = names.get(..count).ok_or(GlError::InvalidValue)?;
        for &name in names {
            self.textures.delete(name);
        }
        Ok(())
    }

    /// glIsTexture.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_texture(GL_TEXTURE_1D, 2)?;
    /// assert_eq!(ctx.is_texture(2)?, GL_TRUE);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn is_texture(&self, name: GLuint) -> GlResult<GLboolean> {
        self.outside_begin_end()?;
        Ok(self.textures.is_texture(name) as GLboolean)
    }

    /// glBindTexture (§3.8.12) on the active unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_texture(GL_TEXTURE_2D, 1)?;
    /// assert_eq!(ctx.get(GL_TEXTURE_BINDING_2D)?.as_ints(), [1]);
    /// // An object keeps the target it was first bound to.
    /// assert_eq!(ctx.bind_texture(GL_TEXTURE_3D, 1), Err(GlError::InvalidOperation));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn bind_texture(&mut self, target: GLenum, name: GLuint) -> GlResult {
        self.outside_begin_end()?;
        let target = Target::of(target).ok_or(GlError::InvalidEnum)?;
        self.textures.bind(target, name)
    }

    /// glAreTexturesResident (§3.8.12): every texture is resident, so GL_TRUE and
    /// `residences` untouched; GL_INVALID_VALUE for a negative count, or a name that is 0 or
    /// no texture.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.bind_texture(GL_TEXTURE_2D, 1)?;
    /// let mut residences = [GL_FALSE; 1];
    /// assert_eq!(ctx.are_textures_resident(1, &[1], &mut residences)?, GL_TRUE);
    /// assert_eq!(ctx.are_textures_resident(1, &[9], &mut residences), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn are_textures_resident(
        &self,
        n: GLsizei,
        names: &[GLuint],
        residences: &mut [GLboolean],
    ) -> GlResult<GLboolean> {
        self.outside_begin_end()?;
        let count = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        let names = names.get(..count).ok_or(GlError::InvalidValue)?;
        if residences.len() < count || names.iter().any(|&t| !self.textures.is_texture(t)) {
            return Err(GlError::InvalidValue);
        }
        Ok(GL_TRUE as GLboolean)
    }

    /// glPrioritizeTextures: priorities clamped to [0, 1]; 0 and names of no texture are
    /// ignored.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.bind_texture(GL_TEXTURE_2D, 1)?;
    /// ctx.prioritize_textures(1, &[1], &[2.0])?;
    /// assert_eq!(ctx.get_tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY)?, [1.0]); // clamped
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn prioritize_textures(
        &mut self,
        n: GLsizei,
        names: &[GLuint],
        priorities: &[f32],
    ) -> GlResult {
        self.outside_begin_end()?;
        let count = usize::try_from(n).map_err(|_| GlError::InvalidValue)?;
        let (Some(names), Some(priorities)) = (names.get(..count), priorities.get(..count)) else {
            return Err(GlError::InvalidValue);
        };
        for (&name, &priority) in names.iter().zip(priorities) {
            if let Some(object) = self.textures.object_mut(name) {
                object.params.priority = priority.clamp(0.0, 1.0);
            }
        }
        Ok(())
    }

    /// The object bound to a glTexParameter / glGetTexParameter target on the active unit.
    fn parameter_object(&mut self, target: GLenum) -> GlResult<&mut TextureObject> {
        self.outside_begin_end()?;
        let target = Target::of(target).ok_or(GlError::InvalidEnum)?;
        Ok(self.textures.bound_mut(target))
    }

    /// glTexParameterfv (§3.8.4).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &[0.5, 2.0, 0.0, 1.0])?;
    /// assert_eq!(ctx.get_tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR)?, [0.5, 1.0, 0.0, 1.0]);
    /// let bad = [GL_LINEAR_MIPMAP_LINEAR as f32];
    /// assert_eq!(ctx.tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &bad), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_parameter(&mut self, target: GLenum, pname: GLenum, params: &[f32]) -> GlResult {
        self.parameter_object(target)?.params.set(pname, params)
    }

    /// glTexParameteriv: the border color maps integers to [-1, 1] (then clamped), the
    /// other values convert directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_parameter_i(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, &[GL_CLAMP_TO_EDGE as i32])?;
    /// assert_eq!(ctx.get_tex_parameter_i(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S)?, [GL_CLAMP_TO_EDGE as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_parameter_i(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) -> GlResult {
        let floats = int_params(params, pname == GL_TEXTURE_BORDER_COLOR);
        self.tex_parameter(target, pname, &floats)
    }

    /// glTexParameterf / glTexParameteri: GL_INVALID_ENUM for the border color, which has
    /// four values.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.tex_parameter_scalar(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4.0)?;
    /// assert_eq!(ctx.tex_parameter_scalar(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1.0), Err(GlError::InvalidEnum));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_parameter_scalar(&mut self, target: GLenum, pname: GLenum, param: f32) -> GlResult {
        self.parameter_object(target)?;
        if tex_parameter_count(pname) != Some(1) {
            return Err(GlError::InvalidEnum);
        }
        self.tex_parameter(target, pname, &[param])
    }

    /// glGetTexParameter (§6.1.3), in the value's own type.
    fn tex_parameter_value(&mut self, target: GLenum, pname: GLenum) -> GlResult<StateValue> {
        let params = &self.parameter_object(target)?.params;
        let float = |v: f32| StateValue::Floats(vec![v as f64]);
        Ok(match pname {
            GL_TEXTURE_MIN_FILTER => enumeration(params.min_filter),
            GL_TEXTURE_MAG_FILTER => enumeration(params.mag_filter),
            GL_TEXTURE_WRAP_S => enumeration(params.wrap[0]),
            GL_TEXTURE_WRAP_T => enumeration(params.wrap[1]),
            GL_TEXTURE_WRAP_R => enumeration(params.wrap[2]),
            GL_TEXTURE_BORDER_COLOR => {
                StateValue::Normalized(params.border_color.iter().map(|&c| c as f64).collect())
            }
            // Normalized when read as an integer, as Mesa does.
            GL_TEXTURE_PRIORITY => StateValue::Normalized(vec![params.priority as f64]),
            GL_TEXTURE_MIN_LOD => float(params.min_lod),
            GL_TEXTURE_MAX_LOD => float(params.max_lod),
            GL_TEXTURE_BASE_LEVEL => int(params.base_level),
            GL_TEXTURE_MAX_LEVEL => int(params.max_level),
            GL_GENERATE_MIPMAP => StateValue::Bools(vec![params.generate_mipmap]),
            GL_DEPTH_TEXTURE_MODE => enumeration(params.depth_texture_mode),
            GL_TEXTURE_COMPARE_MODE => enumeration(params.compare_mode),
            GL_TEXTURE_COMPARE_FUNC => enumeration(params.compare_func),
            GL_TEXTURE_RESIDENT => StateValue::Bools(vec![true]),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetTexParameterfv.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.get_tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER)?, [GL_NEAREST_MIPMAP_LINEAR as f32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_parameter(&mut self, target: GLenum, pname: GLenum) -> GlResult<Vec<f32>> {
        Ok(self.tex_parameter_value(target, pname)?.as_floats())
    }

    /// glGetTexParameteriv: the border color and priority mapped to integers (§6.1.2).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.get_tex_parameter_i(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY)?, [i32::MAX]); // 1.0
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_parameter_i(&mut self, target: GLenum, pname: GLenum) -> GlResult<Vec<GLint>> {
        Ok(self.tex_parameter_value(target, pname)?.as_ints())
    }

    /// glTexEnvfv (§3.8.13) on the active unit.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.25, 0.5, 0.75, 1.0])?;
    /// assert_eq!(ctx.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR)?, [0.25, 0.5, 0.75, 1.0]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_env(&mut self, target: GLenum, pname: GLenum, params: &[f32]) -> GlResult {
        self.outside_begin_end()?;
        self.textures.unit_mut().env.set(target, pname, params)
    }

    /// glTexEnviv: the color maps integers to [-1, 1] (then clamped), the others convert
    /// directly.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.tex_env_i(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &[GL_DECAL as i32])?;
    /// assert_eq!(ctx.get_tex_env_i(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE)?, [GL_DECAL as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_env_i(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) -> GlResult {
        let floats = int_params(params, pname == GL_TEXTURE_ENV_COLOR);
        self.tex_env(target, pname, &floats)
    }

    /// glTexEnvf / glTexEnvi: GL_INVALID_ENUM for the color, which has four values.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.tex_env_scalar(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0)?;
    /// assert_eq!(ctx.tex_env_scalar(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0), Err(GlError::InvalidValue)); // 1, 2 or 4
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_env_scalar(&mut self, target: GLenum, pname: GLenum, param: f32) -> GlResult {
        self.outside_begin_end()?;
        if matches!(target, GL_TEXTURE_ENV | GL_TEXTURE_FILTER_CONTROL)
            && tex_env_count(target, pname) == Some(4)
        {
            return Err(GlError::InvalidEnum);
        }
        self.tex_env(target, pname, &[param])
    }

    /// glGetTexEnvfv (§6.1.3).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE)?, [GL_MODULATE as f32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_env(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<f32>> {
        self.outside_begin_end()?;
        Ok(self.textures.unit().env.get(target, pname)?.0)
    }

    /// glGetTexEnviv: the color mapped to integers (§6.1.2), scales and the LOD bias rounded.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_tex_env_i(GL_TEXTURE_ENV, GL_COMBINE_RGB)?, [GL_MODULATE as i32]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_env_i(&self, target: GLenum, pname: GLenum) -> GlResult<Vec<GLint>> {
        self.outside_begin_end()?;
        let (values, float) = self.textures.unit().env.get(target, pname)?;
        Ok(match pname {
            GL_TEXTURE_ENV_COLOR => values.iter().map(|&c| color_to_int(c)).collect(),
            _ if float => values.iter().map(|&v| float_to_int(v)).collect(),
            _ => values.iter().map(|&v| v as GLint).collect(),
        })
    }

    /// The texture values of glGet (tables 6.15-6.20, 6.30), or None for a pname that is not
    /// theirs.
    pub(crate) fn get_texture_state(&self, pname: GLenum) -> Option<StateValue> {
        let unit = self.textures.unit();
        if let Some(target) = Target::ALL.into_iter().find(|t| t.binding_pname() == pname) {
            return Some(int(unit.bindings[target as usize] as GLint));
        }
        Some(match pname {
            GL_ACTIVE_TEXTURE => enumeration(GL_TEXTURE0 + self.textures.active_unit as GLenum),
            GL_CLIENT_ACTIVE_TEXTURE => {
                enumeration(GL_TEXTURE0 + self.arrays.client_active_texture as GLenum)
            }
            GL_MAX_TEXTURE_UNITS => int(MAX_TEXTURE_UNITS as GLint),
            GL_MAX_TEXTURE_SIZE => int(Target::Texture2D.max_size()),
            GL_MAX_3D_TEXTURE_SIZE => int(Target::Texture3D.max_size()),
            GL_MAX_CUBE_MAP_TEXTURE_SIZE => int(Target::CubeMap.max_size()),
            GL_MAX_TEXTURE_LOD_BIAS => super::query::floats(&[MAX_TEXTURE_LOD_BIAS]),
            GL_NUM_COMPRESSED_TEXTURE_FORMATS => int(0),
            GL_COMPRESSED_TEXTURE_FORMATS => StateValue::Ints(Vec::new()),
            _ => return None,
        })
    }

    /// The images of an image target: the bound object's, or the proxy's.
    fn images_mut(
        &mut self,
        image: ImageTarget,
    ) -> &mut std::collections::BTreeMap<(usize, usize), TexImage> {
        if image.proxy {
            &mut self.textures.proxies[image.target as usize]
        } else {
            &mut self.textures.bound_mut(image.target).images
        }
    }

    fn image(&self, image: ImageTarget, level: usize) -> Option<&TexImage> {
        let images = if image.proxy {
            &self.textures.proxies[image.target as usize]
        } else {
            &self.textures.bound(image.target).images
        };
        images.get(&(image.face, level))
    }

    /// The bytes glTexImage reads at its pointer under the unpack modes (0 for arguments
    /// the command rejects).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::TexImageArgs, gl::*, Context};
    /// let ctx = Context::new();
    /// let args = TexImageArgs {
    ///     target: GL_TEXTURE_2D, level: 0, internal_format: GL_RGB as i32,
    ///     size: [3, 2, 1], border: 0, format: GL_RGB, ty: GL_UNSIGNED_BYTE,
    /// };
    /// // Rows of 9 bytes padded to the unpack alignment of 4; the last row unpadded.
    /// assert_eq!(ctx.tex_image_span(2, &args), 12 + 9);
    /// ```
    pub fn tex_image_span(&self, dimensions: usize, args: &TexImageArgs) -> usize {
        let Ok(format) = PixelFormat::new(args.format, args.ty) else {
            return 0;
        };
        let size = image_size(dimensions, args.size);
        if size.iter().any(|&s| s < 0) {
            return 0;
        }
        let size = size.map(|s| s as usize);
        Layout::new(&self.pixel_store.unpack, &format, size, dimensions == 3).span()
    }

    /// The bytes glTexSubImage reads.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::SubImageArgs, gl::*, Context};
    /// let ctx = Context::new();
    /// let args = SubImageArgs {
    ///     target: GL_TEXTURE_2D, level: 0, offset: [0, 0, 0], size: [2, 2, 1],
    ///     format: GL_RGBA, ty: GL_UNSIGNED_BYTE,
    /// };
    /// assert_eq!(ctx.tex_sub_image_span(2, &args), 16);
    /// ```
    pub fn tex_sub_image_span(&self, dimensions: usize, args: &SubImageArgs) -> usize {
        self.tex_image_span(
            dimensions,
            &TexImageArgs {
                target: args.target,
                level: args.level,
                internal_format: 0,
                size: args.size,
                border: 0,
                format: args.format,
                ty: args.ty,
            },
        )
    }

    /// The checks of an image specification shared by glTexImage and glCopyTexImage
    /// (Mesa's order): level, border, sizes, the internal format (GL_INVALID_VALUE), a
    /// cube map face that is not square. Returns the image target, level and format.
    fn check_image_spec(
        &self,
        image: ImageTarget,
        level: GLint,
        internal: GLint,
        size: [GLsizei; 3],
        border: GLint,
        format: GlResult<Option<PixelFormat>>,
    ) -> GlResult<(usize, Base, [u8; 7])> {
        let level = image.check_level(level)?;
        if !(0..=1).contains(&border) || size.iter().any(|&s| s < 0) {
            return Err(GlError::InvalidValue);
        }
        let format = format?;
        let (base, sizes) = internal_format(internal).ok_or(GlError::InvalidValue)?;
        if let Some(format) = format
            && format.depth != (base == Base::Depth)
        {
            return Err(GlError::InvalidOperation);
        }
        if base == Base::Depth && matches!(image.target, Target::Texture3D | Target::CubeMap) {
            return Err(GlError::InvalidOperation);
        }
        if image.target == Target::CubeMap && size[0] != size[1] {
            return Err(GlError::InvalidValue);
        }
        Ok((level, base, sizes))
    }

    /// Stores a new image, or for a proxy its state only (zeroed when it could not be made:
    /// a size GL 1.5 does not take). GL_INVALID_VALUE for such a size otherwise.
    #[allow(clippy::too_many_arguments)]
    fn define_image(
        &mut self,
        image: ImageTarget,
        level: usize,
        internal: GLint,
        (base, sizes): (Base, [u8; 7]),
        size: [GLsizei; 3],
        border: GLint,
        texels: impl FnOnce(&Context, [usize; 3]) -> GlResult<Vec<[f32; 4]>>,
    ) -> GlResult {
        let dimensions = image.target.dimensions();
        let max = image.target.max_size();
        let legal = (0..dimensions).all(|i| legal_size(size[i], border, max));
        if image.proxy {
            let images = self.images_mut(image);
            if legal {
                images.insert(
                    (0, level),
                    TexImage {
                        width: size[0],
                        height: size[1],
                        depth: size[2],
                        border,
                        internal_format: internal,
                        base,
                        sizes,
                        texels: Arc::default(),
                    },
                );
            } else {
                images.remove(&(0, level));
            }
            return Ok(());
        }
        if !legal {
            return Err(GlError::InvalidValue);
        }
        let texels = texels(self, size.map(|s| s as usize))?;
        let new = TexImage {
            width: size[0],
            height: size[1],
            depth: size[2],
            border,
            internal_format: internal,
            base,
            sizes,
            texels: Arc::new(texels),
        };
        self.images_mut(image).insert((image.face, level), new);
        self.generate_mipmaps(image, level);
        Ok(())
    }

    /// Unpacks client pixels into texels of `base` (transfer, then table 3.15's conversion).
    fn unpack_texels(
        &self,
        pixels: &[u8],
        format: &PixelFormat,
        size: [usize; 3],
        three_d: bool,
        (base, sizes): (Base, [u8; 7]),
    ) -> GlResult<Vec<[f32; 4]>> {
        let modes = &self.pixel_store.unpack;
        let layout = Layout::new(modes, format, size, three_d);
        let convert = |rgba| {
            TexImage::store(
                base,
                &sizes,
                transfer(&self.pixel_mode, &self.pixel_maps, rgba, format.depth),
            )
        };
        if pixels.is_empty() && layout.span() > 0 {
            // A NULL pointer: the image's contents are undefined; fflight zeroes them.
            return Ok(vec![[0.0; 4]; size.iter().product()]);
        }
        unpack(pixels, modes, format, &layout, convert)
    }

    /// glTexImage1D / 2D / 3D (§3.8.1): `pixels` holds `tex_image_span` bytes, or is empty
    /// (NULL: an image of zeros). Mesa's order of checks: target, level, border, sizes,
    /// format and type, internal format, their agreement, then the sizes GL 1.5 takes
    /// (powers of two plus the border, at most the maximum: for a proxy, no error but a
    /// zeroed proxy image).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::TexImageArgs, gl::*, Context};
    /// let mut ctx = Context::new();
    /// let args = TexImageArgs {
    ///     target: GL_TEXTURE_2D, level: 0, internal_format: GL_RGBA8 as i32,
    ///     size: [2, 2, 1], border: 0, format: GL_RGBA, ty: GL_UNSIGNED_BYTE,
    /// };
    /// let texels: Vec<u8> = (0..16).map(|i| i * 16).collect();
    /// ctx.tex_image(2, &args, &texels)?;
    /// assert_eq!(ctx.get_tex_level_parameter(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH)?, [2]);
    /// let mut back = vec![0u8; 16];
    /// ctx.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut back)?;
    /// assert_eq!(back, texels);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_image(&mut self, dimensions: usize, args: &TexImageArgs, pixels: &[u8]) -> GlResult {
        self.outside_begin_end()?;
        let image = ImageTarget::of(args.target, dimensions, true)?;
        let size = image_size(dimensions, args.size);
        let format = PixelFormat::new(args.format, args.ty);
        let (level, base, sizes) = self.check_image_spec(
            image,
            args.level,
            args.internal_format,
            size,
            args.border,
            format.map(Some),
        )?;
        let format = format?;
        self.define_image(
            image,
            level,
            args.internal_format,
            (base, sizes),
            size,
            args.border,
            |ctx, size| ctx.unpack_texels(pixels, &format, size, dimensions == 3, (base, sizes)),
        )
    }

    /// glCopyTexImage1D / 2D (§3.8.2). fflight's framebuffer holds nothing drawn: every
    /// pixel read is (0, 0, 0, 0) (depth 0), which then goes through pixel transfer like
    /// any copied pixel. The unsized internal formats 1-4 are GL_INVALID_VALUE here.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// ctx.copy_tex_image(2, GL_TEXTURE_2D, 0, GL_RGBA as i32, [4, 4], 0)?;
    /// assert_eq!(ctx.get_tex_level_parameter(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT)?, [4]);
    /// let mut texels = vec![1u8; 64];
    /// ctx.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut texels)?;
    /// assert!(texels.iter().all(|&b| b == 0)); // the empty framebuffer's pixels
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image(
        &mut self,
        dimensions: usize,
        target: GLenum,
        level: GLint,
        internal: GLint,
        size: [GLsizei; 2],
        border: GLint,
    ) -> GlResult {
        self.outside_begin_end()?;
        let image = ImageTarget::of(target, dimensions, false)?;
        let size = image_size(dimensions, [size[0], size[1], 1]);
        if (1..=4).contains(&internal) {
            image.check_level(level)?;
            return Err(GlError::InvalidValue);
        }
        let (level, base, sizes) =
            self.check_image_spec(image, level, internal, size, border, Ok(None))?;
        self.define_image(
            image,
            level,
            internal,
            (base, sizes),
            size,
            border,
            |ctx, size| {
                Ok(vec![
                    ctx.framebuffer_texel(base, &sizes);
                    size.iter().product()
                ])
            },
        )
    }

    /// What a copy from the framebuffer gives one texel: the empty framebuffer's (0, 0, 0, 0)
    /// after pixel transfer.
    fn framebuffer_texel(&self, base: Base, sizes: &[u8; 7]) -> [f32; 4] {
        let depth = base == Base::Depth;
        let pixel = transfer(&self.pixel_mode, &self.pixel_maps, [0.0; 4], depth);
        TexImage::store(base, sizes, pixel)
    }

    /// The checks of glTexSubImage and glCopyTexSubImage (Mesa's order after the target:
    /// level, sizes, format and type, the image's existence (GL_INVALID_OPERATION), the
    /// region within the image, the format's agreement). Returns the image target and level.
    fn check_sub_image(
        &self,
        dimensions: usize,
        args: &SubImageArgs,
        format: GlResult<Option<PixelFormat>>,
    ) -> GlResult<(ImageTarget, usize)> {
        self.outside_begin_end()?;
        let image = ImageTarget::of(args.target, dimensions, false)?;
        let level = image.check_level(args.level)?;
        let size = image_size(dimensions, args.size);
        if size.iter().any(|&s| s < 0) {
            return Err(GlError::InvalidValue);
        }
        let format = format?;
        let current = self.image(image, level).ok_or(GlError::InvalidOperation)?;
        let extent = [current.width, current.height, current.depth];
        for i in 0..dimensions {
            let (offset, b) = (args.offset[i] as i64, current.border as i64);
            if offset < -b || offset + size[i] as i64 > extent[i] as i64 - b {
                return Err(GlError::InvalidValue);
            }
        }
        if let Some(format) = format
            && format.depth != (current.base == Base::Depth)
        {
            return Err(GlError::InvalidOperation);
        }
        Ok((image, level))
    }

    /// Replaces the texels of a region of an image with `texels` (in region order), then
    /// regenerates the mipmaps if they are generated from this level.
    fn replace_region(
        &mut self,
        image: ImageTarget,
        level: usize,
        offset: [GLint; 3],
        size: [usize; 3],
        texels: Vec<[f32; 4]>,
    ) {
        let Some(current) = self.images_mut(image).get_mut(&(image.face, level)) else {
            return;
        };
        let b = current.border;
        let (w, h) = (current.width as usize, current.height as usize);
        let dimensions = image.target.dimensions();
        let origin: [usize; 3] = std::array::from_fn(|i| {
            if i < dimensions {
                (offset[i] + b) as usize
            } else {
                0
            }
        });
        let store = Arc::make_mut(&mut current.texels);
        let mut source = texels.into_iter();
        for z in 0..size[2] {
            for y in 0..size[1] {
                for x in 0..size[0] {
                    let at = ((origin[2] + z) * h + origin[1] + y) * w + origin[0] + x;
                    if let Some(texel) = source.next() {
                        store[at] = texel;
                    }
                }
            }
        }
        self.generate_mipmaps(image, level);
    }

    /// glTexSubImage1D / 2D / 3D (§3.8.2): `pixels` holds `tex_sub_image_span` bytes; empty
    /// (NULL) changes nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::{SubImageArgs, TexImageArgs}, gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let image = TexImageArgs {
    ///     target: GL_TEXTURE_1D, level: 0, internal_format: GL_RGBA8 as i32,
    ///     size: [4, 1, 1], border: 0, format: GL_RGBA, ty: GL_UNSIGNED_BYTE,
    /// };
    /// ctx.tex_image(1, &image, &[])?; // zeros
    /// let region = SubImageArgs {
    ///     target: GL_TEXTURE_1D, level: 0, offset: [1, 0, 0], size: [1, 1, 1],
    ///     format: GL_RGBA, ty: GL_UNSIGNED_BYTE,
    /// };
    /// ctx.tex_sub_image(1, &region, &[255, 255, 255, 255])?;
    /// let mut back = [0u8; 16];
    /// ctx.get_tex_image(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut back)?;
    /// assert_eq!(back[4..8], [255; 4]);
    /// let outside = SubImageArgs { offset: [4, 0, 0], ..region };
    /// assert_eq!(ctx.tex_sub_image(1, &outside, &[0; 4]), Err(GlError::InvalidValue));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn tex_sub_image(
        &mut self,
        dimensions: usize,
        args: &SubImageArgs,
        pixels: &[u8],
    ) -> GlResult {
        let format = PixelFormat::new(args.format, args.ty);
        let (image, level) = self.check_sub_image(dimensions, args, format.map(Some))?;
        let format = format?;
        let size = image_size(dimensions, args.size).map(|s| s as usize);
        let current = self.image(image, level).expect("checked");
        let layout = Layout::new(&self.pixel_store.unpack, &format, size, dimensions == 3);
        if pixels.is_empty() && layout.span() > 0 {
            return Ok(());
        }
        let texels = self.unpack_texels(
            pixels,
            &format,
            size,
            dimensions == 3,
            (current.base, current.sizes),
        )?;
        self.replace_region(image, level, args.offset, size, texels);
        Ok(())
    }

    /// glCopyTexSubImage1D / 2D / 3D (§3.8.2): the region gets the empty framebuffer's
    /// pixels (see `copy_tex_image`).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{commands::texture::SubImageArgs, gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// let region = SubImageArgs {
    ///     target: GL_TEXTURE_2D, level: 0, offset: [0, 0, 0], size: [1, 1, 1],
    ///     format: GL_RGBA, ty: GL_UNSIGNED_BYTE,
    /// };
    /// // No image at level 0 yet.
    /// assert_eq!(ctx.copy_tex_sub_image(2, &region), Err(GlError::InvalidOperation));
    /// ```
    pub fn copy_tex_sub_image(&mut self, dimensions: usize, args: &SubImageArgs) -> GlResult {
        let (image, level) = self.check_sub_image(dimensions, args, Ok(None))?;
        let size = image_size(dimensions, args.size).map(|s| s as usize);
        let current = self.image(image, level).expect("checked");
        let texel = self.framebuffer_texel(current.base, &current.sizes);
        let texels = vec![texel; size.iter().product()];
        self.replace_region(image, level, args.offset, size, texels);
        Ok(())
    }

    /// GL_GENERATE_MIPMAP (§3.8.8): after a change to the base level of an object whose
    /// parameter is set, every level below it down to 1 x 1 (or the max level) is made
    /// again, each texel the mean of the 2, 4 or 8 texels above it. Images with a border
    /// are not reduced (fflight's choice).
    fn generate_mipmaps(&mut self, image: ImageTarget, level: usize) {
        if image.proxy {
            return;
        }
        let object = self.textures.bound_mut(image.target);
        let params = &object.params;
        if !params.generate_mipmap || level as GLint != params.base_level {
            return;
        }
        let last = (params.max_level as usize).min(image.target.levels() - 1);
        let mut level = level;
        while level < last {
            let Some(above) = object.images.get(&(image.face, level)) else {
                return;
            };
            if above.border != 0 || (above.width <= 1 && above.height <= 1 && above.depth <= 1) {
                return;
            }
            let next = reduce(above);
            level += 1;
            object.images.insert((image.face, level), next);
        }
    }

    /// glGetTexLevelParameterfv / iv (§6.1.3): an image that does not exist reports width,
    /// height, depth, border and sizes 0 and internal format 1 (table 6.17).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let ctx = Context::new();
    /// // No image: width 0 and internal format 1.
    /// assert_eq!(ctx.get_tex_level_parameter(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH)?, [0]);
    /// assert_eq!(ctx.get_tex_level_parameter(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT)?, [1]);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_level_parameter(
        &self,
        target: GLenum,
        level: GLint,
        pname: GLenum,
    ) -> GlResult<Vec<GLint>> {
        self.outside_begin_end()?;
        let image = ImageTarget::any(target, true)?;
        let level = image.check_level(level)?;
        let current = self.image(image, level);
        let get = |f: fn(&TexImage) -> GLint, absent: GLint| current.map_or(absent, f);
        let value = match pname {
            GL_TEXTURE_WIDTH => get(|i| i.width, 0),
            GL_TEXTURE_HEIGHT => get(|i| i.height, 0),
            GL_TEXTURE_DEPTH => get(|i| i.depth, 0),
            GL_TEXTURE_BORDER => get(|i| i.border, 0),
            GL_TEXTURE_INTERNAL_FORMAT => get(|i| i.internal_format, 1),
            GL_TEXTURE_COMPRESSED => 0,
            // No image is compressed.
            GL_TEXTURE_COMPRESSED_IMAGE_SIZE => return Err(GlError::InvalidOperation),
            _ => {
                let probe = TexImage {
                    width: 0,
                    height: 0,
                    depth: 0,
                    border: 0,
                    internal_format: 1,
                    base: Base::Rgba,
                    sizes: [0; 7],
                    texels: Arc::default(),
                };
                let size = current
                    .unwrap_or(&probe)
                    .size(pname)
                    .ok_or(GlError::InvalidEnum)?;
                size as GLint
            }
        };
        Ok(vec![value])
    }

    /// The bytes glGetTexImage writes under the pack modes (0 for arguments it rejects or an
    /// image that does not exist).
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.get_tex_image_span(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE), 0); // no image
    /// ctx.copy_tex_image(2, GL_TEXTURE_2D, 0, GL_RGB as i32, [2, 2], 0)?;
    /// assert_eq!(ctx.get_tex_image_span(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT), 2 * 2 * 16);
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_image_span(
        &self,
        target: GLenum,
        level: GLint,
        format: GLenum,
        ty: GLenum,
    ) -> usize {
        let (Ok(image), Ok(format)) = (
            ImageTarget::any(target, false),
            PixelFormat::new(format, ty),
        ) else {
            return 0;
        };
        let Ok(level) = image.check_level(level) else {
            return 0;
        };
        self.image(image, level).map_or(0, |current| {
            let size = [current.width, current.height, current.depth].map(|s| s as usize);
            Layout::new(
                &self.pixel_store.pack,
                &format,
                size,
                image.target == Target::Texture3D,
            )
            .span()
        })
    }

    /// glGetTexImage (§6.1.4): the image as RGBA (table 6.1), packed with the pack modes and
    /// no pixel transfer into `pixels` (`get_tex_image_span` bytes). GL_INVALID_OPERATION for
    /// a depth format and a color image or the other way round; nothing is written for an
    /// image that does not exist.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// ctx.copy_tex_image(2, GL_TEXTURE_2D, 0, GL_RGBA as i32, [1, 1], 0)?;
    /// let mut out = [0u8; 4];
    /// ctx.get_tex_image(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, &mut out)?;
    /// // A color image read as depth.
    /// assert_eq!(ctx.get_tex_image(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &mut out), Err(GlError::InvalidOperation));
    /// # Ok::<(), fflight::GlError>(())
    /// ```
    pub fn get_tex_image(
        &self,
        target: GLenum,
        level: GLint,
        format: GLenum,
        ty: GLenum,
        pixels: &mut [u8],
    ) -> GlResult {
        self.outside_begin_end()?;
        let image = ImageTarget::any(target, false)?;
        let level = image.check_level(level)?;
        let format = PixelFormat::new(format, ty)?;
        let Some(current) = self.image(image, level) else {
            return Ok(());
        };
        if format.depth != (current.base == Base::Depth) {
            return Err(GlError::InvalidOperation);
        }
        let size = [current.width, current.height, current.depth].map(|s| s as usize);
        let layout = Layout::new(
            &self.pixel_store.pack,
            &format,
            size,
            image.target == Target::Texture3D,
        );
        if pixels.len() < layout.span() {
            return Err(GlError::InvalidValue);
        }
        let colors: Vec<[f32; 4]> = current.texels.iter().map(|&t| current.rgba(t)).collect();
        pack(&colors, pixels, &self.pixel_store.pack, &format, &layout)
    }

    /// glCompressedTexImage1D / 2D / 3D (§3.8.3): fflight supports no compressed format
    /// (GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0), so every internal format given is
    /// GL_INVALID_ENUM, as is a bad target.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{Context, GlError};
    /// assert_eq!(Context::new().compressed_tex_image(), Err(GlError::InvalidEnum));
    /// ```
    pub fn compressed_tex_image(&mut self) -> GlResult {
        self.outside_begin_end()?;
        Err(GlError::InvalidEnum)
    }

    /// glCompressedTexSubImage1D / 2D / 3D (§3.8.3): GL_INVALID_ENUM for a bad target,
    /// GL_INVALID_VALUE for a bad level, else GL_INVALID_OPERATION: no image is compressed,
    /// so the format never matches the image's.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let mut ctx = Context::new();
    /// assert_eq!(ctx.compressed_tex_sub_image(2, GL_TEXTURE_2D, 0), Err(GlError::InvalidOperation));
    /// assert_eq!(ctx.compressed_tex_sub_image(2, GL_TEXTURE_2D, -1), Err(GlError::InvalidValue));
    /// ```
    pub fn compressed_tex_sub_image(
        &mut self,
        dimensions: usize,
        target: GLenum,
        level: GLint,
    ) -> GlResult {
        self.outside_begin_end()?;
        ImageTarget::of(target, dimensions, false)?.check_level(level)?;
        Err(GlError::InvalidOperation)
    }

    /// glGetCompressedTexImage (§6.1.4): GL_INVALID_ENUM for a bad target, GL_INVALID_VALUE
    /// for a bad level, else GL_INVALID_OPERATION: no image is compressed.
    ///
    /// # Examples
    ///
    /// ```
    /// use fflight::{gl::*, Context, GlError};
    /// let ctx = Context::new();
    /// assert_eq!(ctx.get_compressed_tex_image(GL_TEXTURE_2D, 0), Err(GlError::InvalidOperation));
    /// assert_eq!(ctx.get_compressed_tex_image(GL_LIGHT0, 0), Err(GlError::InvalidEnum));
    /// ```
    pub fn get_compressed_tex_image(&self, target: GLenum, level: GLint) -> GlResult {
        self.outside_begin_end()?;
        ImageTarget::any(target, false)?.check_level(level)?;
        Err(GlError::InvalidOperation)
    }
}

/// The next smaller mipmap level of `image`: each size halved (not below 1), each texel the
/// mean of the texels it covers, quantized to the image's resolution.
fn reduce(image: &TexImage) -> TexImage {
    let size = [image.width, image.height, image.depth].map(|s| s as usize);
    let next = size.map(|s| (s / 2).max(1));
    let factor: [usize; 3] = std::array::from_fn(|i| size[i] / next[i]);
    let mut texels = Vec::with_capacity(next.iter().product());
    for z in 0..next[2] {
        for y in 0..next[1] {
            for x in 0..next[0] {
                let mut sum = [0.0f64; 4];
                let mut n = 0.0;
                for dz in 0..factor[2] {
                    for dy in 0..factor[1] {
                        for dx in 0..factor[0] {
                            let (sx, sy, sz) =
                                (x * factor[0] + dx, y * factor[1] + dy, z * factor[2] + dz);
                            let texel = image.texels[(sz * size[1] + sy) * size[0] + sx];
                            for (s, t) in sum.iter_mut().zip(texel) {
                                *s += t as f64;
                            }
                            n += 1.0;
                        }
                    }
                }
                let mean = sum.map(|s| (s / n) as f32);
                // `store` keeps the base format's components where they are.
                texels.push(TexImage::store(
                    image.base,
                    &image.sizes,
                    from_stored(image.base, mean),
                ));
            }
        }
    }
    TexImage {
        width: next[0] as i32,
        height: next[1] as i32,
        depth: next[2] as i32,
        texels: Arc::new(texels),
        ..image.clone()
    }
}

/// A stored texel as the RGBA color `TexImage::store` takes back unchanged.
fn from_stored(base: Base, texel: [f32; 4]) -> [f32; 4] {
    let [r, _, _, a] = texel;
    match base {
        Base::Alpha => [0.0, 0.0, 0.0, a],
        _ => [r, texel[1], texel[2], a],
    }
}
