//! The state that does not change vertex processing (points, lines, polygons, fog, hints,
//! per-fragment operations, framebuffer control, pixels): the initial values of the GL 1.5
//! state tables, values set and read back through glGet, and every error path, which must
//! change nothing (§2.5). Through `fflight::Context`; tests/c_programs.rs runs the same
//! commands from C against OSMesa.

use fflight::commands::query::StateValue;
use fflight::gl::*;
use fflight::state::pixel::StoreParam;
use fflight::{Context, GlError, GlResult};
use glam::Vec4;

#[path = "common/state_lists.rs"]
mod state_lists;

use state_lists::*;

/// The capabilities kept in the attribute groups.
const CAPABILITIES: [GLenum; 22] = [
    GL_POINT_SMOOTH,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_POLYGON_SMOOTH,
    GL_POLYGON_STIPPLE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL,
    GL_FOG,
    GL_COLOR_SUM,
    GL_SCISSOR_TEST,
    GL_ALPHA_TEST,
    GL_STENCIL_TEST,
    GL_DEPTH_TEST,
    GL_BLEND,
    GL_DITHER,
    GL_INDEX_LOGIC_OP,
    GL_COLOR_LOGIC_OP,
    GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
];

/// Every glGet pname of this state (the ones of tests/common/state_lists.rs and those it had
/// before), and its capabilities.
fn pnames() -> Vec<GLenum> {
    let older = [
        GL_POINT_SIZE,
        GL_LINE_WIDTH,
        GL_COLOR_CLEAR_VALUE,
        GL_DEPTH_CLEAR_VALUE,
        GL_PERSPECTIVE_CORRECTION_HINT,
        GL_POINT_SMOOTH_HINT,
        GL_LINE_SMOOTH_HINT,
        GL_POLYGON_SMOOTH_HINT,
        GL_FOG_HINT,
    ];
    [&older[..], &state_pnames(), &CAPABILITIES].concat()
}

/// Everything the queries report of this state, the stipple and the pixel maps included.
fn snapshot(ctx: &Context) -> Vec<String> {
    let mut out: Vec<String> = pnames()
        .iter()
        .map(|&p| format!("{p:#x} {:?}", ctx.get(p)))
        .collect();
    let mut stipple = [0u8; 128];
    out.push(format!("{:?}", ctx.get_polygon_stipple(&mut stipple)));
    out.push(format!("{stipple:?}"));
    for map in PIXEL_MAPS {
        out.push(format!("{map:#x} {:?}", ctx.get_pixel_map(map)));
    }
    out
}

/// The first entry where two snapshots differ, if any.
fn first_difference(before: &[String], after: &[String]) -> Option<(String, String)> {
    before
        .iter()
        .zip(after)
        .find(|(a, b)| a != b)
        .map(|(a, b)| (a.clone(), b.clone()))
}

fn doubles(ctx: &Context, pname: GLenum) -> Vec<f64> {
    ctx.get(pname).expect("a valid pname").as_doubles()
}

fn ints(ctx: &Context, pname: GLenum) -> Vec<i32> {
    ctx.get(pname).expect("a valid pname").as_ints()
}

#[test]
fn initial_values_are_the_state_tables() {
    let ctx = Context::new();
    let e = |v: GLenum| vec![v as f64];
    let expected: &[(GLenum, Vec<f64>)] = &[
        (GL_POINT_SIZE, vec![1.0]),
        (GL_POINT_SIZE_MIN, vec![0.0]),
        (GL_POINT_SIZE_MAX, vec![1024.0]),
        (GL_POINT_FADE_THRESHOLD_SIZE, vec![1.0]),
        (GL_POINT_DISTANCE_ATTENUATION, vec![1.0, 0.0, 0.0]),
        (GL_LINE_WIDTH, vec![1.0]),
        (GL_LINE_STIPPLE_PATTERN, vec![65535.0]),
        (GL_LINE_STIPPLE_REPEAT, vec![1.0]),
        (GL_POLYGON_OFFSET_FACTOR, vec![0.0]),
        (GL_POLYGON_OFFSET_UNITS, vec![0.0]),
        (GL_FOG_COLOR, vec![0.0; 4]),
        (GL_FOG_INDEX, vec![0.0]),
        (GL_FOG_DENSITY, vec![1.0]),
        (GL_FOG_START, vec![0.0]),
        (GL_FOG_END, vec![1.0]),
        (GL_FOG_MODE, e(GL_EXP)),
        (GL_FOG_COORD_SRC, e(GL_FRAGMENT_DEPTH)),
        (GL_FOG_HINT, e(GL_DONT_CARE)),
        (GL_GENERATE_MIPMAP_HINT, e(GL_DONT_CARE)),
        (GL_TEXTURE_COMPRESSION_HINT, e(GL_DONT_CARE)),
        (GL_ALPHA_TEST_FUNC, e(GL_ALWAYS)),
        (GL_ALPHA_TEST_REF, vec![0.0]),
        (GL_STENCIL_FUNC, e(GL_ALWAYS)),
        (GL_STENCIL_REF, vec![0.0]),
        (GL_STENCIL_FAIL, e(GL_KEEP)),
        (GL_STENCIL_PASS_DEPTH_FAIL, e(GL_KEEP)),
        (GL_STENCIL_PASS_DEPTH_PASS, e(GL_KEEP)),
        (GL_STENCIL_CLEAR_VALUE, vec![0.0]),
        (GL_DEPTH_FUNC, e(GL_LESS)),
        (GL_DEPTH_WRITEMASK, vec![1.0]),
        (GL_DEPTH_CLEAR_VALUE, vec![1.0]),
        (GL_BLEND_SRC_RGB, e(GL_ONE)),
        (GL_BLEND_SRC_ALPHA, e(GL_ONE)),
        (GL_BLEND_DST_RGB, e(GL_ZERO)),
        (GL_BLEND_DST_ALPHA, e(GL_ZERO)),
        (GL_BLEND_EQUATION, e(GL_FUNC_ADD)),
        (GL_BLEND_COLOR, vec![0.0; 4]),
        (GL_LOGIC_OP_MODE, e(GL_COPY)),
        (GL_DRAW_BUFFER, e(GL_FRONT)),
        (GL_READ_BUFFER, e(GL_FRONT)),
        (GL_COLOR_WRITEMASK, vec![1.0; 4]),
        (GL_COLOR_CLEAR_VALUE, vec![0.0; 4]),
        (GL_INDEX_CLEAR_VALUE, vec![0.0]),
        (GL_ACCUM_CLEAR_VALUE, vec![0.0; 4]),
        (GL_UNPACK_ALIGNMENT, vec![4.0]),
        (GL_PACK_ALIGNMENT, vec![4.0]),
        (GL_UNPACK_ROW_LENGTH, vec![0.0]),
        (GL_PACK_LSB_FIRST, vec![0.0]),
        (GL_MAP_COLOR, vec![0.0]),
        (GL_INDEX_SHIFT, vec![0.0]),
        (GL_RED_SCALE, vec![1.0]),
        (GL_DEPTH_BIAS, vec![0.0]),
        (GL_ZOOM_X, vec![1.0]),
        (GL_ZOOM_Y, vec![1.0]),
        (GL_PIXEL_MAP_I_TO_I_SIZE, vec![1.0]),
        (GL_PIXEL_MAP_A_TO_A_SIZE, vec![1.0]),
        (GL_DITHER, vec![1.0]),
        (GL_MULTISAMPLE, vec![1.0]),
        (GL_DEPTH_TEST, vec![0.0]),
        (GL_BLEND, vec![0.0]),
        (GL_FOG, vec![0.0]),
        (GL_POLYGON_STIPPLE, vec![0.0]),
        (GL_SAMPLE_COVERAGE, vec![0.0]),
        (GL_SAMPLE_COVERAGE_VALUE, vec![1.0]),
        (GL_SAMPLE_COVERAGE_INVERT, vec![0.0]),
        (GL_SAMPLE_BUFFERS, vec![0.0]),
    ];
    for (pname, values) in expected {
        assert_eq!(&doubles(&ctx, *pname), values, "pname {pname:#x}");
    }
    // "1's" masks: the stencil ones over its 8 bits, the index one all 32.
    assert_eq!(ints(&ctx, GL_STENCIL_VALUE_MASK), [255]);
    assert_eq!(ints(&ctx, GL_STENCIL_WRITEMASK), [255]);
    assert_eq!(ints(&ctx, GL_INDEX_WRITEMASK), [-1]);
    let mut stipple = [0u8; 128];
    ctx.get_polygon_stipple(&mut stipple).unwrap();
    assert_eq!(stipple, [0xFF; 128]);
    for map in PIXEL_MAPS {
        assert_eq!(ctx.get_pixel_map(map), Ok(vec![0.0]));
    }
}

#[test]
fn values_set_read_back() {
    let mut ctx = Context::new();
    ctx.point_size(3.5).unwrap();
    ctx.point_parameter(GL_POINT_DISTANCE_ATTENUATION, &[1.0, 2.0, 3.0])
        .unwrap();
    ctx.point_parameter_i(GL_POINT_SIZE_MIN, &[2]).unwrap();
    ctx.point_parameter_scalar(GL_POINT_FADE_THRESHOLD_SIZE, 0.5)
        .unwrap();
    ctx.line_width(2.5).unwrap();
    ctx.line_stipple(300, 0xF0F0).unwrap();
    ctx.polygon_offset(1.5, -2.0).unwrap();
    ctx.fog(GL_FOG_COLOR, &[0.25, 2.0, -1.0, 0.5]).unwrap();
    ctx.fog_i(GL_FOG_MODE, &[GL_LINEAR as i32]).unwrap();
    ctx.fog_scalar(GL_FOG_DENSITY, 0.75).unwrap();
    ctx.fog_scalar(GL_FOG_COORD_SRC, GL_FOG_COORD as f32)
        .unwrap();
    ctx.hint(GL_GENERATE_MIPMAP_HINT, GL_NICEST).unwrap();
    ctx.scissor(1, 2, 30, 40).unwrap();
    ctx.alpha_func(GL_GEQUAL, 1.5).unwrap();
    ctx.stencil_func(GL_NOTEQUAL, 1000, 0xF0).unwrap();
    ctx.stencil_op(GL_INCR_WRAP, GL_INVERT, GL_REPLACE).unwrap();
    ctx.depth_func(GL_LEQUAL).unwrap();
    ctx.blend_func_separate(
        GL_SRC_ALPHA,
        GL_ONE_MINUS_SRC_ALPHA,
        GL_SRC_ALPHA_SATURATE,
        GL_CONSTANT_ALPHA,
    )
    .unwrap();
    ctx.blend_color(Vec4::new(0.5, -1.0, 2.0, 0.25)).unwrap();
    ctx.blend_equation(GL_FUNC_REVERSE_SUBTRACT).unwrap();
    ctx.logic_op(GL_XOR).unwrap();
    ctx.draw_buffer(GL_NONE).unwrap();
    ctx.index_mask(0x0F).unwrap();
    ctx.color_mask([true, false, true, false]).unwrap();
    ctx.depth_mask(false).unwrap();
    ctx.stencil_mask(0x3C).unwrap();
    ctx.clear_color(Vec4::new(2.0, 0.5, -1.0, 1.0)).unwrap();
    ctx.clear_index(7.5).unwrap();
    ctx.clear_depth(-3.0).unwrap();
    ctx.clear_stencil(5).unwrap();
    ctx.clear_accum(Vec4::new(-2.0, 0.5, 2.0, -0.25)).unwrap();
    ctx.pixel_store(GL_UNPACK_ALIGNMENT, StoreParam::Int(8))
        .unwrap();
    ctx.pixel_store(GL_PACK_ROW_LENGTH, StoreParam::Float(12.6))
        .unwrap();
    ctx.pixel_store(GL_PACK_SWAP_BYTES, StoreParam::Float(0.25))
        .unwrap();
    ctx.pixel_transfer(GL_INDEX_SHIFT, -2.0).unwrap();
    ctx.pixel_transfer(GL_GREEN_BIAS, 0.125).unwrap();
    ctx.pixel_transfer(GL_MAP_STENCIL, 1.0).unwrap();
    ctx.pixel_zoom(2.0, -0.5).unwrap();
    ctx.sample_coverage(1.5, true).unwrap();
    for cap in [GL_DEPTH_TEST, GL_FOG, GL_POLYGON_OFFSET_LINE, GL_COLOR_SUM] {
        ctx.set_capability(cap, true).unwrap();
    }
    ctx.set_capability(GL_DITHER, false).unwrap();

    let expected: &[(GLenum, Vec<f64>)] = &[
        (GL_POINT_SIZE, vec![3.5]),
        (GL_POINT_DISTANCE_ATTENUATION, vec![1.0, 2.0, 3.0]),
        (GL_POINT_SIZE_MIN, vec![2.0]),
        (GL_POINT_FADE_THRESHOLD_SIZE, vec![0.5]),
        (GL_LINE_WIDTH, vec![2.5]),
        (GL_LINE_STIPPLE_REPEAT, vec![256.0]),
        (GL_LINE_STIPPLE_PATTERN, vec![0xF0F0 as f64]),
        (GL_POLYGON_OFFSET_FACTOR, vec![1.5]),
        (GL_POLYGON_OFFSET_UNITS, vec![-2.0]),
        (GL_FOG_COLOR, vec![0.25, 1.0, 0.0, 0.5]),
        (GL_FOG_MODE, vec![GL_LINEAR as f64]),
        (GL_FOG_DENSITY, vec![0.75]),
        (GL_FOG_COORD_SRC, vec![GL_FOG_COORD as f64]),
        (GL_GENERATE_MIPMAP_HINT, vec![GL_NICEST as f64]),
        (GL_SCISSOR_BOX, vec![1.0, 2.0, 30.0, 40.0]),
        (GL_ALPHA_TEST_FUNC, vec![GL_GEQUAL as f64]),
        (GL_ALPHA_TEST_REF, vec![1.0]),
        (GL_STENCIL_FUNC, vec![GL_NOTEQUAL as f64]),
        (GL_STENCIL_REF, vec![255.0]),
        (GL_STENCIL_VALUE_MASK, vec![240.0]),
        (GL_STENCIL_FAIL, vec![GL_INCR_WRAP as f64]),
        (GL_STENCIL_PASS_DEPTH_FAIL, vec![GL_INVERT as f64]),
        (GL_STENCIL_PASS_DEPTH_PASS, vec![GL_REPLACE as f64]),
        (GL_DEPTH_FUNC, vec![GL_LEQUAL as f64]),
        (GL_BLEND_SRC, vec![GL_SRC_ALPHA as f64]),
        (GL_BLEND_DST_RGB, vec![GL_ONE_MINUS_SRC_ALPHA as f64]),
        (GL_BLEND_SRC_ALPHA, vec![GL_SRC_ALPHA_SATURATE as f64]),
        (GL_BLEND_DST_ALPHA, vec![GL_CONSTANT_ALPHA as f64]),
        (GL_BLEND_COLOR, vec![0.5, 0.0, 1.0, 0.25]),
        (GL_BLEND_EQUATION, vec![GL_FUNC_REVERSE_SUBTRACT as f64]),
        (GL_LOGIC_OP_MODE, vec![GL_XOR as f64]),
        (GL_DRAW_BUFFER, vec![GL_NONE as f64]),
        (GL_INDEX_WRITEMASK, vec![15.0]),
        (GL_COLOR_WRITEMASK, vec![1.0, 0.0, 1.0, 0.0]),
        (GL_DEPTH_WRITEMASK, vec![0.0]),
        (GL_STENCIL_WRITEMASK, vec![60.0]),
        (GL_COLOR_CLEAR_VALUE, vec![1.0, 0.5, 0.0, 1.0]),
        (GL_INDEX_CLEAR_VALUE, vec![7.5]),
        (GL_DEPTH_CLEAR_VALUE, vec![0.0]),
        (GL_STENCIL_CLEAR_VALUE, vec![5.0]),
        (GL_ACCUM_CLEAR_VALUE, vec![-1.0, 0.5, 1.0, -0.25]),
        (GL_UNPACK_ALIGNMENT, vec![8.0]),
        (GL_PACK_ROW_LENGTH, vec![13.0]),
        (GL_PACK_SWAP_BYTES, vec![1.0]),
        (GL_INDEX_SHIFT, vec![-2.0]),
        (GL_GREEN_BIAS, vec![0.125]),
        (GL_MAP_STENCIL, vec![1.0]),
        (GL_ZOOM_X, vec![2.0]),
        (GL_ZOOM_Y, vec![-0.5]),
        (GL_SAMPLE_COVERAGE_VALUE, vec![1.0]),
        (GL_SAMPLE_COVERAGE_INVERT, vec![1.0]),
        (GL_DEPTH_TEST, vec![1.0]),
        (GL_FOG, vec![1.0]),
        (GL_POLYGON_OFFSET_LINE, vec![1.0]),
        (GL_COLOR_SUM, vec![1.0]),
        (GL_DITHER, vec![0.0]),
    ];
    for (pname, values) in expected {
        assert_eq!(&doubles(&ctx, *pname), values, "pname {pname:#x}");
        // glIsEnabled agrees with glGet for the capabilities.
        if let Ok(enabled) = ctx.is_enabled(*pname) {
            assert_eq!(enabled as u8 as f64, values[0], "glIsEnabled({pname:#x})");
        }
    }
    // The alpha reference is a color: as an integer it maps [0, 1] to [-2^31, 2^31 - 1].
    assert_eq!(ints(&ctx, GL_ALPHA_TEST_REF), [i32::MAX]);
}

#[test]
fn pixel_maps_convert_and_clamp() {
    let mut ctx = Context::new();
    ctx.pixel_map(GL_PIXEL_MAP_R_TO_R, 3, &[-1.0, 0.5, 2.0])
        .unwrap();
    assert_eq!(
        ctx.get_pixel_map(GL_PIXEL_MAP_R_TO_R),
        Ok(vec![0.0, 0.5, 1.0])
    );
    assert_eq!(ints(&ctx, GL_PIXEL_MAP_R_TO_R_SIZE), [3]);
    ctx.pixel_map(GL_PIXEL_MAP_I_TO_I, 2, &[-3.0, 700.5])
        .unwrap();
    assert_eq!(
        ctx.get_pixel_map(GL_PIXEL_MAP_I_TO_I),
        Ok(vec![-3.0, 700.5])
    );
    ctx.pixel_map_integers(GL_PIXEL_MAP_I_TO_G, 2, &[0u16, 65535], 65535.0)
        .unwrap();
    assert_eq!(ctx.get_pixel_map(GL_PIXEL_MAP_I_TO_G), Ok(vec![0.0, 1.0]));
    ctx.pixel_map_integers(GL_PIXEL_MAP_S_TO_S, 1, &[9u32], u32::MAX as f64)
        .unwrap();
    assert_eq!(ctx.get_pixel_map(GL_PIXEL_MAP_S_TO_S), Ok(vec![9.0]));
    assert_eq!(
        ctx.get_pixel_map_ushort(GL_PIXEL_MAP_I_TO_G),
        Ok(vec![0, 65535])
    );
    assert_eq!(ctx.get_pixel_map_uint(GL_PIXEL_MAP_S_TO_S), Ok(vec![9]));
    ctx.pixel_map(GL_PIXEL_MAP_G_TO_G, 2, &[0.25, 0.75])
        .unwrap();
    assert_eq!(
        ctx.get_pixel_map_uint(GL_PIXEL_MAP_G_TO_G),
        Ok(vec![1073741823, 3221225471])
    );
    assert_eq!(
        ctx.get_pixel_map_ushort(GL_PIXEL_MAP_G_TO_G),
        Ok(vec![16384, 49151])
    );
}

#[test]
fn the_stipple_follows_the_pixel_store_modes() {
    let mut ctx = Context::new();
    let pattern: Vec<u8> = (0..128u32).map(|i| (i * 37 + 11) as u8).collect();
    ctx.polygon_stipple(&pattern).unwrap();
    let mut back = [0u8; 128];
    ctx.get_polygon_stipple(&mut back).unwrap();
    assert_eq!(
        back.to_vec(),
        pattern,
        "default modes: 4 bytes a row, MSB first"
    );

    // LSB first on packing reverses the bits of each byte.
    ctx.pixel_store(GL_PACK_LSB_FIRST, StoreParam::Int(1))
        .unwrap();
    ctx.get_polygon_stipple(&mut back).unwrap();
    let reversed: Vec<u8> = pattern.iter().map(|b| b.reverse_bits()).collect();
    assert_eq!(back.to_vec(), reversed);
    ctx.pixel_store(GL_PACK_LSB_FIRST, StoreParam::Int(0))
        .unwrap();

    // Rows of 6 bytes (row length 48 bits), one row and 8 bits skipped, alignment 2.
    for (pname, value) in [
        (GL_UNPACK_ROW_LENGTH, 48),
        (GL_UNPACK_SKIP_ROWS, 1),
        (GL_UNPACK_SKIP_PIXELS, 8),
        (GL_UNPACK_ALIGNMENT, 2),
    ] {
        ctx.pixel_store(pname, StoreParam::Int(value)).unwrap();
    }
    assert_eq!(ctx.polygon_stipple_unpack_span(), 6 + 31 * 6 + 5);
    let mut memory = vec![0u8; ctx.polygon_stipple_unpack_span()];
    for row in 0..32 {
        let start = 6 + row * 6 + 1;
        memory[start..start + 4].copy_from_slice(&pattern[row * 4..row * 4 + 4]);
    }
    assert_eq!(
        ctx.polygon_stipple(&memory[..memory.len() - 1]),
        Err(GlError::InvalidValue),
        "one byte short"
    );
    ctx.polygon_stipple(&memory).unwrap();
    ctx.get_polygon_stipple(&mut back).unwrap();
    assert_eq!(back.to_vec(), pattern);

    // Packing with a bit offset into rows of 40 bits (8 bytes at alignment 4) leaves the bits
    // around the image alone.
    ctx.pixel_store(GL_PACK_SKIP_PIXELS, StoreParam::Int(4))
        .unwrap();
    ctx.pixel_store(GL_PACK_ROW_LENGTH, StoreParam::Int(40))
        .unwrap();
    let mut packed = vec![0xAAu8; ctx.polygon_stipple_pack_span()];
    assert_eq!(packed.len(), 31 * 8 + 5);
    ctx.get_polygon_stipple(&mut packed).unwrap();
    assert_eq!(packed[0] >> 4, 0xA, "the skipped bits");
    assert_eq!(packed[0] & 0xF, pattern[0] >> 4);
    assert_eq!(packed[4] & 0xF, 0xA, "the bits after the row");
    assert_eq!(packed[4] >> 4, pattern[3] & 0xF);
}

type Command = fn(&mut Context) -> GlResult;

/// Calls GL must reject, and the error each gives.
const BAD_CALLS: &[(&str, Command, GlError)] = &[
    ("point size 0", |c| c.point_size(0.0), GlError::InvalidValue),
    (
        "point size NaN",
        |c| c.point_size(f32::NAN),
        GlError::InvalidValue,
    ),
    (
        "point parameter pname",
        |c| c.point_parameter(GL_POINT_SIZE, &[1.0]),
        GlError::InvalidEnum,
    ),
    (
        "point size min < 0",
        |c| c.point_parameter(GL_POINT_SIZE_MIN, &[-1.0]),
        GlError::InvalidValue,
    ),
    (
        "point fade < 0",
        |c| c.point_parameter_i(GL_POINT_FADE_THRESHOLD_SIZE, &[-1]),
        GlError::InvalidValue,
    ),
    (
        "point attenuation scalar",
        |c| c.point_parameter_scalar(GL_POINT_DISTANCE_ATTENUATION, 1.0),
        GlError::InvalidEnum,
    ),
    (
        "point attenuation short",
        |c| c.point_parameter(GL_POINT_DISTANCE_ATTENUATION, &[1.0, 2.0]),
        GlError::InvalidValue,
    ),
    (
        "point parameter NULL",
        |c| c.point_parameter(GL_POINT_SIZE_MAX, &[]),
        GlError::InvalidValue,
    ),
    (
        "line width -1",
        |c| c.line_width(-1.0),
        GlError::InvalidValue,
    ),
    (
        "stipple short",
        |c| c.polygon_stipple(&[0; 127]),
        GlError::InvalidValue,
    ),
    (
        "fog pname",
        |c| c.fog(GL_FOG_HINT, &[1.0]),
        GlError::InvalidEnum,
    ),
    (
        "fog mode",
        |c| c.fog_i(GL_FOG_MODE, &[GL_LINEAR as i32 + 3]),
        GlError::InvalidEnum,
    ),
    (
        "fog density < 0",
        |c| c.fog_scalar(GL_FOG_DENSITY, -0.5),
        GlError::InvalidValue,
    ),
    (
        "fog color scalar",
        |c| c.fog_scalar(GL_FOG_COLOR, 0.5),
        GlError::InvalidEnum,
    ),
    (
        "fog color short",
        |c| c.fog(GL_FOG_COLOR, &[0.5; 3]),
        GlError::InvalidValue,
    ),
    (
        "fog coord src",
        |c| c.fog_scalar(GL_FOG_COORD_SRC, GL_FOG as f32),
        GlError::InvalidEnum,
    ),
    (
        "hint target",
        |c| c.hint(GL_FOG, GL_NICEST),
        GlError::InvalidEnum,
    ),
    (
        "hint mode",
        |c| c.hint(GL_FOG_HINT, GL_FOG),
        GlError::InvalidEnum,
    ),
    (
        "scissor width",
        |c| c.scissor(0, 0, -1, 5),
        GlError::InvalidValue,
    ),
    (
        "scissor height",
        |c| c.scissor(0, 0, 5, -1),
        GlError::InvalidValue,
    ),
    (
        "alpha func",
        |c| c.alpha_func(GL_NEVER - 1, 0.5),
        GlError::InvalidEnum,
    ),
    (
        "stencil func",
        |c| c.stencil_func(GL_ALWAYS + 1, 1, 1),
        GlError::InvalidEnum,
    ),
    (
        "stencil op fail",
        |c| c.stencil_op(GL_ONE, GL_KEEP, GL_KEEP),
        GlError::InvalidEnum,
    ),
    (
        "stencil op zpass",
        |c| c.stencil_op(GL_KEEP, GL_KEEP, GL_DECR_WRAP + 1),
        GlError::InvalidEnum,
    ),
    (
        "depth func",
        |c| c.depth_func(GL_LESS | 0x10),
        GlError::InvalidEnum,
    ),
    (
        "blend src",
        |c| c.blend_func(GL_SRC_ALPHA_SATURATE + 1, GL_ZERO),
        GlError::InvalidEnum,
    ),
    (
        "blend dst saturate",
        |c| c.blend_func(GL_ONE, GL_SRC_ALPHA_SATURATE),
        GlError::InvalidEnum,
    ),
    (
        "blend separate dst alpha",
        |c| c.blend_func_separate(GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD),
        GlError::InvalidEnum,
    ),
    (
        "blend equation",
        |c| c.blend_equation(GL_ONE),
        GlError::InvalidEnum,
    ),
    ("logic op", |c| c.logic_op(GL_SET + 1), GlError::InvalidEnum),
    (
        "draw buffer back",
        |c| c.draw_buffer(GL_BACK),
        GlError::InvalidOperation,
    ),
    (
        "draw buffer aux",
        |c| c.draw_buffer(GL_AUX0),
        GlError::InvalidOperation,
    ),
    (
        "draw buffer enum",
        |c| c.draw_buffer(GL_DEPTH_TEST),
        GlError::InvalidEnum,
    ),
    (
        "read buffer none",
        |c| c.read_buffer(GL_NONE),
        GlError::InvalidEnum,
    ),
    (
        "read buffer both",
        |c| c.read_buffer(GL_FRONT_AND_BACK),
        GlError::InvalidEnum,
    ),
    (
        "read buffer right",
        |c| c.read_buffer(GL_RIGHT),
        GlError::InvalidOperation,
    ),
    (
        "clear mask",
        |c| c.clear(GL_COLOR_BUFFER_BIT | 1),
        GlError::InvalidValue,
    ),
    (
        "accum op",
        |c| c.accum(GL_ADD + 1, 1.0),
        GlError::InvalidEnum,
    ),
    (
        "accum without a buffer",
        |c| c.accum(GL_LOAD, 1.0),
        GlError::InvalidOperation,
    ),
    (
        "pixel store pname",
        |c| c.pixel_store(GL_ZOOM_X, StoreParam::Int(1)),
        GlError::InvalidEnum,
    ),
    (
        "pixel store alignment",
        |c| c.pixel_store(GL_PACK_ALIGNMENT, StoreParam::Int(3)),
        GlError::InvalidValue,
    ),
    (
        "pixel store negative",
        |c| c.pixel_store(GL_UNPACK_SKIP_ROWS, StoreParam::Float(-0.75)),
        GlError::InvalidValue,
    ),
    (
        "pixel transfer pname",
        |c| c.pixel_transfer(GL_ZOOM_Y, 1.0),
        GlError::InvalidEnum,
    ),
    (
        "pixel map size 0",
        |c| c.pixel_map(GL_PIXEL_MAP_R_TO_R, 0, &[]),
        GlError::InvalidValue,
    ),
    (
        "pixel map size > max",
        |c| c.pixel_map(GL_PIXEL_MAP_R_TO_R, 257, &[0.0; 257]),
        GlError::InvalidValue,
    ),
    (
        "pixel map not power of two",
        |c| c.pixel_map(GL_PIXEL_MAP_I_TO_A, 3, &[0.0; 3]),
        GlError::InvalidValue,
    ),
    (
        "pixel map name",
        |c| c.pixel_map(GL_PIXEL_MAP_A_TO_A + 1, 2, &[0.0; 2]),
        GlError::InvalidEnum,
    ),
    (
        "pixel map size before name",
        |c| c.pixel_map(GL_FOG, -1, &[]),
        GlError::InvalidValue,
    ),
    (
        "pixel map NULL",
        |c| c.pixel_map(GL_PIXEL_MAP_B_TO_B, 2, &[]),
        GlError::InvalidValue,
    ),
    (
        "get pixel map name",
        |c| c.get_pixel_map(GL_PIXEL_MAP_I_TO_I - 1).map(drop),
        GlError::InvalidEnum,
    ),
    (
        "enable",
        |c| c.set_capability(GL_FOG_HINT, true),
        GlError::InvalidEnum,
    ),
    (
        "get",
        |c| c.get(GL_FOG_COORD).map(drop),
        GlError::InvalidEnum,
    ),
];

/// A context whose state differs from the initial one almost everywhere, so that a bad call
/// resetting something would show.
fn busy_context() -> Context {
    let mut ctx = Context::new();
    ctx.point_size(2.0).unwrap();
    ctx.fog(GL_FOG_COLOR, &[0.1, 0.2, 0.3, 0.4]).unwrap();
    ctx.fog_scalar(GL_FOG_MODE, GL_EXP2 as f32).unwrap();
    ctx.scissor(3, 4, 5, 6).unwrap();
    ctx.stencil_func(GL_LESS, 3, 7).unwrap();
    ctx.blend_func(GL_DST_COLOR, GL_SRC_COLOR).unwrap();
    ctx.pixel_map(GL_PIXEL_MAP_I_TO_R, 4, &[0.1, 0.2, 0.3, 0.4])
        .unwrap();
    ctx.pixel_store(GL_PACK_ALIGNMENT, StoreParam::Int(1))
        .unwrap();
    ctx.polygon_stipple(&[0x5A; 128]).unwrap();
    ctx.set_capability(GL_BLEND, true).unwrap();
    ctx
}

#[test]
fn errors_change_nothing() {
    for (name, command, error) in BAD_CALLS {
        let mut ctx = busy_context();
        let before = snapshot(&ctx);
        assert_eq!(command(&mut ctx), Err(*error), "{name}");
        let change = first_difference(&before, &snapshot(&ctx));
        assert_eq!(change, None, "{name} changed the state");
    }
}

/// Every command of this state, with valid arguments that change it.
const GOOD_CALLS: &[(&str, Command)] = &[
    ("glPointSize", |c| c.point_size(4.0)),
    ("glPointParameterfv", |c| {
        c.point_parameter(GL_POINT_SIZE_MAX, &[9.0])
    }),
    ("glPointParameteri", |c| {
        c.point_parameter_scalar(GL_POINT_SIZE_MIN, 3.0)
    }),
    ("glLineWidth", |c| c.line_width(4.0)),
    ("glLineStipple", |c| c.line_stipple(2, 0x0F0F)),
    ("glPolygonOffset", |c| c.polygon_offset(1.0, 1.0)),
    ("glPolygonStipple", |c| c.polygon_stipple(&[0x11; 128])),
    ("glFogfv", |c| c.fog(GL_FOG_START, &[-1.0])),
    ("glFogi", |c| c.fog_scalar(GL_FOG_INDEX, 3.0)),
    ("glHint", |c| c.hint(GL_LINE_SMOOTH_HINT, GL_FASTEST)),
    ("glScissor", |c| c.scissor(0, 0, 1, 1)),
    ("glAlphaFunc", |c| c.alpha_func(GL_LESS, 0.5)),
    ("glStencilFunc", |c| c.stencil_func(GL_EQUAL, 1, 1)),
    ("glStencilOp", |c| c.stencil_op(GL_ZERO, GL_ZERO, GL_ZERO)),
    ("glDepthFunc", |c| c.depth_func(GL_GREATER)),
    ("glBlendFunc", |c| c.blend_func(GL_ZERO, GL_ONE)),
    ("glBlendColor", |c| c.blend_color(Vec4::ONE)),
    ("glBlendEquation", |c| c.blend_equation(GL_MAX)),
    ("glLogicOp", |c| c.logic_op(GL_NAND)),
    ("glDrawBuffer", |c| c.draw_buffer(GL_FRONT_AND_BACK)),
    ("glReadBuffer", |c| c.read_buffer(GL_LEFT)),
    ("glIndexMask", |c| c.index_mask(1)),
    ("glColorMask", |c| c.color_mask([false; 4])),
    ("glDepthMask", |c| c.depth_mask(false)),
    ("glStencilMask", |c| c.stencil_mask(1)),
    ("glClearColor", |c| c.clear_color(Vec4::ONE)),
    ("glClearIndex", |c| c.clear_index(1.0)),
    ("glClearDepth", |c| c.clear_depth(0.5)),
    ("glClearStencil", |c| c.clear_stencil(1)),
    ("glClearAccum", |c| c.clear_accum(Vec4::ONE)),
    ("glPixelStorei", |c| {
        c.pixel_store(GL_UNPACK_LSB_FIRST, StoreParam::Int(1))
    }),
    ("glPixelTransferf", |c| c.pixel_transfer(GL_RED_SCALE, 2.0)),
    ("glPixelMapfv", |c| {
        c.pixel_map(GL_PIXEL_MAP_A_TO_A, 1, &[0.5])
    }),
    ("glPixelZoom", |c| c.pixel_zoom(3.0, 3.0)),
    ("glSampleCoverage", |c| c.sample_coverage(0.5, true)),
    ("glEnable", |c| c.set_capability(GL_STENCIL_TEST, true)),
];

/// §2.6.3: none of these commands is allowed between glBegin and glEnd; there they are
/// GL_INVALID_OPERATION and change nothing. Outside, each changes the state (so the check is
/// not vacuous).
#[test]
fn between_begin_and_end_every_command_is_invalid_operation() {
    for (name, command) in GOOD_CALLS {
        let mut ctx = busy_context();
        let before = snapshot(&ctx);
        ctx.begin(GL_POINTS).unwrap();
        assert_eq!(command(&mut ctx), Err(GlError::InvalidOperation), "{name}");
        ctx.end().unwrap();
        let change = first_difference(&before, &snapshot(&ctx));
        assert_eq!(change, None, "{name} between glBegin and glEnd");
        command(&mut ctx).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        assert!(
            first_difference(&before, &snapshot(&ctx)).is_some(),
            "{name} changed nothing"
        );
    }
    let mut ctx = Context::new();
    ctx.begin(GL_POINTS).unwrap();
    assert_eq!(ctx.get(GL_FOG_MODE), Err(GlError::InvalidOperation));
    let mut stipple = [0u8; 128];
    assert_eq!(
        ctx.get_polygon_stipple(&mut stipple),
        Err(GlError::InvalidOperation)
    );
    assert_eq!(
        ctx.get_pixel_map(GL_PIXEL_MAP_I_TO_I),
        Err(GlError::InvalidOperation)
    );
    assert!(matches!(ctx.get(GL_BLEND), Err(GlError::InvalidOperation)));
}

#[test]
fn capabilities_read_back_through_get_and_is_enabled() {
    let mut ctx = Context::new();
    for cap in CAPABILITIES {
        for enabled in [true, false, true] {
            ctx.set_capability(cap, enabled).unwrap();
            assert_eq!(ctx.is_enabled(cap), Ok(enabled), "{cap:#x}");
            assert_eq!(
                ctx.get(cap),
                Ok(StateValue::Bools(vec![enabled])),
                "{cap:#x}"
            );
        }
    }
}

/// glRect{s,i,f,d}v (made from the entry-point table) draw what glRect draws; a missing corner
/// (a NULL pointer) is GL_INVALID_VALUE and draws nothing.
#[test]
fn rect_from_vectors_is_rect() {
    let captured = |draw: &dyn Fn(&mut Context) -> GlResult| {
        let mut ctx = Context::new();
        ctx.capture_begin().unwrap();
        let result = draw(&mut ctx);
        ctx.capture_end().unwrap();
        let eye: Vec<Vec4> = ctx.captured().vertices().iter().map(|v| v.eye).collect();
        (result, eye)
    };
    let (ok, expected) = captured(&|c| c.rect(-1.0, 2.0, 3.0, 5.0));
    assert_eq!((ok, expected.len()), (Ok(()), 4));
    assert_eq!(
        captured(&|c| c.rect_v(&[-1i16, 2], &[3i16, 5])),
        (Ok(()), expected.clone())
    );
    assert_eq!(
        captured(&|c| c.rect_v(&[-1i32, 2], &[3i32, 5])),
        (Ok(()), expected.clone())
    );
    assert_eq!(
        captured(&|c| c.rect_v(&[-1.0f64, 2.0], &[3.0, 5.0])),
        (Ok(()), expected)
    );
    assert_eq!(
        captured(&|c| c.rect_v::<i32>(&[], &[3, 5])),
        (Err(GlError::InvalidValue), vec![])
    );
}
