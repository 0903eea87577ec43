//! Integer <-> float conversions of §2.14 (table 2.9) and §6.1.2.

use crate::gl::*;

/// A signed 32-bit integer color component mapped linearly to [-1, 1]: (2c + 1) / (2^32 - 1).
///
/// # Examples
///
/// ```
/// use fflight::state::convert::int_to_color;
/// assert_eq!((int_to_color(i32::MAX), int_to_color(i32::MIN)), (1.0, -1.0));
/// ```
pub fn int_to_color(c: i32) -> f32 {
    ((2.0 * c as f64 + 1.0) / 4_294_967_295.0) as f32
}

/// The integer parameters of a glFogiv, glTexParameteriv, glTexEnviv ... as floats: colors by
/// `int_to_color`, other values converted directly.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::int_params;
/// assert_eq!(int_params(&[i32::MAX, 0, 0, i32::MAX], true)[0], 1.0);
/// assert_eq!(int_params(&[45], false), [45.0]);
/// ```
pub fn int_params(params: &[i32], is_color: bool) -> Vec<f32> {
    params
        .iter()
        .map(|&p| if is_color { int_to_color(p) } else { p as f32 })
        .collect()
}

/// A float color component mapped back to a signed 32-bit integer (§6.1.2), clamped. The
/// mapping puts 0.0 exactly halfway between -1 and 0; ties round up, so 0.0 reads back as 0.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::color_to_int;
/// assert_eq!((color_to_int(1.0), color_to_int(-1.0), color_to_int(0.0)), (i32::MAX, i32::MIN, 0));
/// ```
pub fn color_to_int(f: f32) -> i32 {
    normalized_to_int(f as f64)
}

/// `color_to_int` of a value GL keeps in double precision (the depth range), without first
/// rounding it to a float: 0.2 reads back as 429496729, not 429496735.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::normalized_to_int;
/// assert_eq!(normalized_to_int(0.2), 429496729);
/// ```
pub fn normalized_to_int(f: f64) -> i32 {
    let value = ((4_294_967_295.0 * f) - 1.0) / 2.0;
    (value + 0.5)
        .floor()
        .clamp(i32::MIN as f64, i32::MAX as f64) as i32
}

/// Any other float state as an integer: rounded to the nearest (§6.1.2), clamped.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::float_to_int;
/// assert_eq!((float_to_int(2.4), float_to_int(2.6), float_to_int(1e20)), (2, 3, i32::MAX));
/// ```
pub fn float_to_int(f: f32) -> i32 {
    (f as f64).round().clamp(i32::MIN as f64, i32::MAX as f64) as i32
}

/// A signed byte component (normals, colors) mapped to [-1, 1]: (2c + 1) / 255.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::byte_to_float;
/// assert_eq!((byte_to_float(127), byte_to_float(-128)), (1.0, -1.0));
/// ```
pub fn byte_to_float(c: i8) -> f32 {
    (2.0 * c as f32 + 1.0) / 255.0
}

/// A signed short component mapped to [-1, 1]: (2c + 1) / 65535.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::short_to_float;
/// assert_eq!((short_to_float(32767), short_to_float(-32768)), (1.0, -1.0));
/// ```
pub fn short_to_float(c: i16) -> f32 {
    ((2.0 * c as f64 + 1.0) / 65535.0) as f32
}

/// An unsigned byte component mapped to [0, 1].
///
/// # Examples
///
/// ```
/// use fflight::state::convert::ubyte_to_float;
/// assert_eq!((ubyte_to_float(0), ubyte_to_float(255)), (0.0, 1.0));
/// ```
pub fn ubyte_to_float(c: u8) -> f32 {
    c as f32 / 255.0
}

/// An unsigned short component mapped to [0, 1].
///
/// # Examples
///
/// ```
/// use fflight::state::convert::ushort_to_float;
/// assert_eq!(ushort_to_float(65535), 1.0);
/// ```
pub fn ushort_to_float(c: u16) -> f32 {
    (c as f64 / 65535.0) as f32
}

/// An unsigned int component mapped to [0, 1].
///
/// # Examples
///
/// ```
/// use fflight::state::convert::uint_to_float;
/// assert_eq!(uint_to_float(u32::MAX), 1.0);
/// ```
pub fn uint_to_float(c: u32) -> f32 {
    (c as f64 / 4_294_967_295.0) as f32
}

/// A GL component type, as the typed entry points (glColor3ub, glNormal3s ...) pass it.
pub trait Component: Copy {
    /// Normalized per table 2.9: signed types to [-1, 1], unsigned to [0, 1], floats as they are.
    fn normalized(self) -> f32;
    /// Converted directly, as vertex and texture coordinates are.
    fn direct(self) -> f32;
}

macro_rules! component {
    ($t:ty, $normalize:expr) => {
        impl Component for $t {
            fn normalized(self) -> f32 {
                $normalize(self)
            }
            fn direct(self) -> f32 {
                self as f32
            }
        }
    };
}

component!(i8, byte_to_float);
component!(u8, ubyte_to_float);
component!(i16, short_to_float);
component!(u16, ushort_to_float);
component!(i32, int_to_color);
component!(u32, uint_to_float);
component!(f32, |v: f32| v);
component!(f64, |v: f64| v as f32);

/// A GLfixed value (OpenGL ES 1.1 §2.1.2: 16.16 two's complement) as a float: x / 65536,
/// exact in double, rounded once to float.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::fixed;
/// assert_eq!((fixed(65536), fixed(-32768)), (1.0, -0.5));
/// ```
pub fn fixed(x: i32) -> f32 {
    fixed_f64(x) as f32
}

/// A 16.16 fixed-point value in double, exactly.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::fixed_f64;
/// assert_eq!(fixed_f64(1), 1.0 / 65536.0);
/// ```
pub fn fixed_f64(x: i32) -> f64 {
    f64::from(x) / 65536.0
}

/// A value as GLfixed, for glGetFixedv and the `x` queries: times 65536, rounded to the
/// nearest integer, saturated to the GLfixed range (NaN gives 0).
///
/// # Examples
///
/// ```
/// use fflight::state::convert::to_fixed;
/// assert_eq!((to_fixed(1.5), to_fixed(f64::NAN), to_fixed(1e10)), (98304, 0, i32::MAX));
/// ```
pub fn to_fixed(v: f64) -> i32 {
    (v * 65536.0).round() as i32
}

/// A GLfixed parameter of glFogx, glTexEnvx, glTexParameterx or glLightModelx: enumerated
/// and boolean parameters (GL_FOG_MODE, GL_TEXTURE_ENV_MODE, the combiner's, filters and
/// wrap modes, GL_LIGHT_MODEL_TWO_SIDE, ...) carry their value itself, as OpenGL ES 1.1
/// passes them; the others are 16.16.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::convert::fixed_param};
/// assert_eq!(fixed_param(GL_FOG_DENSITY, 32768), 0.5);
/// assert_eq!(fixed_param(GL_FOG_MODE, GL_LINEAR as i32), GL_LINEAR as f32); // an enum passes
/// ```
pub fn fixed_param(pname: GLenum, x: i32) -> f32 {
    let as_is = matches!(
        pname,
        GL_FOG_MODE
            | GL_FOG_COORD_SRC
            | GL_TEXTURE_ENV_MODE
            | GL_COMBINE_RGB
            | GL_COMBINE_ALPHA
            | GL_SOURCE0_RGB..=GL_SOURCE2_ALPHA
            | GL_OPERAND0_RGB..=GL_OPERAND2_ALPHA
            | GL_TEXTURE_MIN_FILTER
            | GL_TEXTURE_MAG_FILTER
            | GL_TEXTURE_WRAP_S
            | GL_TEXTURE_WRAP_T
            | GL_TEXTURE_WRAP_R
            | GL_GENERATE_MIPMAP
            | GL_TEXTURE_COMPARE_MODE
            | GL_TEXTURE_COMPARE_FUNC
            | GL_DEPTH_TEXTURE_MODE
            | GL_TEXTURE_BASE_LEVEL
            | GL_TEXTURE_MAX_LEVEL
            | GL_LIGHT_MODEL_TWO_SIDE
            | GL_LIGHT_MODEL_LOCAL_VIEWER
            | GL_LIGHT_MODEL_COLOR_CONTROL
    );
    if as_is { x as f32 } else { fixed(x) }
}

/// `fixed_param` of each value.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::convert::fixed_params};
/// assert_eq!(fixed_params(GL_FOG_COLOR, &[65536, 0, 0, 65536]), [1.0, 0.0, 0.0, 1.0]);
/// ```
pub fn fixed_params(pname: GLenum, values: &[i32]) -> Vec<f32> {
    values.iter().map(|&x| fixed_param(pname, x)).collect()
}

/// Values as GLfixed.
///
/// # Examples
///
/// ```
/// use fflight::state::convert::to_fixed_all;
/// assert_eq!(to_fixed_all(&[1.0, 0.25]), [65536, 16384]);
/// ```
pub fn to_fixed_all(values: &[f32]) -> Vec<i32> {
    values.iter().map(|&v| to_fixed(f64::from(v))).collect()
}

/// The values of a glGetTexEnvxv or glGetTexParameterxv: enumerated ones as they are, the
/// others as 16.16.
///
/// # Examples
///
/// ```
/// use fflight::{gl::*, state::convert::fixed_query};
/// assert_eq!(fixed_query(GL_FOG_DENSITY, &[0.5]), [32768]);
/// assert_eq!(fixed_query(GL_FOG_MODE, &[GL_EXP as f32]), [GL_EXP as i32]);
/// ```
pub fn fixed_query(pname: GLenum, values: &[f32]) -> Vec<i32> {
    let as_is = fixed_param(pname, 1) == 1.0;
    values
        .iter()
        .map(|&v| {
            if as_is {
                v as i32
            } else {
                to_fixed(f64::from(v))
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_ends_map_to_plus_minus_one() {
        assert_eq!(int_to_color(i32::MAX), 1.0);
        assert_eq!(int_to_color(i32::MIN), -1.0);
        assert_eq!(byte_to_float(127), 1.0);
        assert_eq!(byte_to_float(-128), -1.0);
        assert_eq!(short_to_float(i16::MAX), 1.0);
        assert_eq!(ubyte_to_float(255), 1.0);
        assert_eq!(uint_to_float(u32::MAX), 1.0);
    }

    #[test]
    fn colors_round_trip_through_integers() {
        assert_eq!(color_to_int(1.0), i32::MAX);
        assert_eq!(color_to_int(-1.0), i32::MIN);
        assert_eq!(color_to_int(0.0), 0);
        assert_eq!(float_to_int(2.5), 3);
        assert_eq!(float_to_int(-0.4), 0);
    }
}
