//! Attribute stacks (§6.1.14): for each bit of glPushAttrib and glPushClientAttrib, every
//! queryable state the state tables assign to it (their "Attribute" column) comes back on pop,
//! and every other state keeps its new value. The assignment of each query to its bits is
//! written here from the tables, independently of the implementation's groups.

#[path = "common/state_lists.rs"]
mod state_lists;

use fflight::commands::attrib_stack::ENABLE_BIT_CAPABILITIES;
use fflight::gl::*;
use fflight::state::enables::TEXTURE_CAPABILITIES;
use fflight::state::hints::HINT_TARGETS;
use fflight::state::pixel::StoreParam;
use fflight::state::texture::MAX_TEXTURE_UNITS;
use fflight::{Context, GlError};
use glam::{Vec3, Vec4};
use state_lists::*;

/// A server bit or a client bit: the two stacks' bits overlap in value.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Bits {
    Server(GLbitfield),
    Client(GLbitfield),
    /// State in no attribute group (matrices, pixel maps, buffer objects' contents).
    None,
}

/// One queryable piece of state, the bits that save it and how to read it.
struct Item {
    name: String,
    bits: Bits,
    read: Box<dyn Fn(&Context) -> String>,
}

fn get(pname: GLenum, bits: Bits) -> Item {
    Item {
        name: format!("glGet 0x{pname:04X}"),
        bits,
        read: Box::new(move |ctx| format!("{:?}", ctx.get(pname))),
    }
}

fn server(bits: GLbitfield) -> Bits {
    Bits::Server(bits)
}

/// Every state item, with its bits, from the state tables 6.5-6.29.
fn items() -> Vec<Item> {
    let mut items = Vec::new();
    let mut gets = |pnames: &[GLenum], bits: Bits| {
        items.extend(pnames.iter().map(|&p| get(p, bits)));
    };
    gets(
        &[
            GL_CURRENT_COLOR,
            GL_CURRENT_NORMAL,
            GL_EDGE_FLAG,
            GL_CURRENT_RASTER_POSITION,
            GL_CURRENT_RASTER_POSITION_VALID,
            GL_CURRENT_RASTER_COLOR,
            GL_CURRENT_RASTER_SECONDARY_COLOR,
            GL_CURRENT_RASTER_DISTANCE,
            GL_CURRENT_SECONDARY_COLOR,
            GL_CURRENT_FOG_COORD,
            GL_CURRENT_INDEX,
        ],
        server(GL_CURRENT_BIT),
    );
    gets(&[GL_LIST_BASE], server(GL_LIST_BIT));
    gets(
        &[
            GL_COLOR_TABLE,
            GL_POST_CONVOLUTION_COLOR_TABLE,
            GL_POST_COLOR_MATRIX_COLOR_TABLE,
            GL_CONVOLUTION_1D,
            GL_CONVOLUTION_2D,
            GL_SEPARABLE_2D,
            GL_HISTOGRAM,
            GL_MINMAX,
        ],
        server(GL_PIXEL_MODE_BIT | GL_ENABLE_BIT),
    );
    gets(&[GL_ACTIVE_TEXTURE], server(GL_TEXTURE_BIT));
    gets(&[GL_POINT_SIZE], server(GL_POINT_BIT));
    gets(&POINT_PNAMES, server(GL_POINT_BIT));
    gets(&[GL_POINT_SMOOTH], server(GL_POINT_BIT | GL_ENABLE_BIT));
    gets(
        &[
            GL_LINE_WIDTH,
            GL_LINE_STIPPLE_PATTERN,
            GL_LINE_STIPPLE_REPEAT,
        ],
        server(GL_LINE_BIT),
    );
    gets(
        &[GL_LINE_SMOOTH, GL_LINE_STIPPLE],
        server(GL_LINE_BIT | GL_ENABLE_BIT),
    );
    gets(
        &[
            GL_CULL_FACE_MODE,
            GL_FRONT_FACE,
            GL_POLYGON_MODE,
            GL_POLYGON_OFFSET_FACTOR,
            GL_POLYGON_OFFSET_UNITS,
        ],
        server(GL_POLYGON_BIT),
    );
    gets(
        &[
            GL_CULL_FACE,
            GL_POLYGON_SMOOTH,
            GL_POLYGON_STIPPLE,
            GL_POLYGON_OFFSET_POINT,
            GL_POLYGON_OFFSET_LINE,
            GL_POLYGON_OFFSET_FILL,
        ],
        server(GL_POLYGON_BIT | GL_ENABLE_BIT),
    );
    gets(&PIXEL_TRANSFER_PNAMES, server(GL_PIXEL_MODE_BIT));
    gets(
        &[GL_ZOOM_X, GL_ZOOM_Y, GL_READ_BUFFER],
        server(GL_PIXEL_MODE_BIT),
    );
    gets(
        &[
            GL_LIGHT_MODEL_AMBIENT,
            GL_LIGHT_MODEL_LOCAL_VIEWER,
            GL_LIGHT_MODEL_TWO_SIDE,
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_COLOR_MATERIAL_FACE,
            GL_COLOR_MATERIAL_PARAMETER,
            GL_SHADE_MODEL,
        ],
        server(GL_LIGHTING_BIT),
    );
    gets(
        &[GL_LIGHTING, GL_COLOR_MATERIAL],
        server(GL_LIGHTING_BIT | GL_ENABLE_BIT),
    );
    gets(&FOG_PNAMES, server(GL_FOG_BIT));
    gets(&[GL_FOG, GL_COLOR_SUM], server(GL_FOG_BIT | GL_ENABLE_BIT));
    gets(
        &[GL_DEPTH_FUNC, GL_DEPTH_CLEAR_VALUE, GL_DEPTH_WRITEMASK],
        server(GL_DEPTH_BUFFER_BIT),
    );
    gets(
        &[GL_DEPTH_TEST],
        server(GL_DEPTH_BUFFER_BIT | GL_ENABLE_BIT),
    );
    gets(&[GL_ACCUM_CLEAR_VALUE], server(GL_ACCUM_BUFFER_BIT));
    gets(
        &[
            GL_STENCIL_FUNC,
            GL_STENCIL_VALUE_MASK,
            GL_STENCIL_REF,
            GL_STENCIL_FAIL,
            GL_STENCIL_PASS_DEPTH_FAIL,
            GL_STENCIL_PASS_DEPTH_PASS,
            GL_STENCIL_CLEAR_VALUE,
            GL_STENCIL_WRITEMASK,
        ],
        server(GL_STENCIL_BUFFER_BIT),
    );
    gets(
        &[GL_STENCIL_TEST],
        server(GL_STENCIL_BUFFER_BIT | GL_ENABLE_BIT),
    );
    gets(&[GL_VIEWPORT, GL_DEPTH_RANGE], server(GL_VIEWPORT_BIT));
    gets(&[GL_MATRIX_MODE], server(GL_TRANSFORM_BIT));
    gets(
        &[GL_NORMALIZE, GL_RESCALE_NORMAL],
        server(GL_TRANSFORM_BIT | GL_ENABLE_BIT),
    );
    gets(
        &[
            GL_ALPHA_TEST_FUNC,
            GL_ALPHA_TEST_REF,
            GL_BLEND_SRC_RGB,
            GL_BLEND_DST_RGB,
            GL_BLEND_SRC_ALPHA,
            GL_BLEND_DST_ALPHA,
            GL_BLEND_EQUATION,
            GL_BLEND_COLOR,
            GL_LOGIC_OP_MODE,
            GL_DRAW_BUFFER,
            GL_INDEX_WRITEMASK,
            GL_COLOR_WRITEMASK,
            GL_COLOR_CLEAR_VALUE,
            GL_INDEX_CLEAR_VALUE,
        ],
        server(GL_COLOR_BUFFER_BIT),
    );
    gets(
        &[
            GL_ALPHA_TEST,
            GL_BLEND,
            GL_DITHER,
            GL_INDEX_LOGIC_OP,
            GL_COLOR_LOGIC_OP,
        ],
        server(GL_COLOR_BUFFER_BIT | GL_ENABLE_BIT),
    );
    gets(&HINT_TARGETS, server(GL_HINT_BIT));
    gets(&[GL_SCISSOR_BOX], server(GL_SCISSOR_BIT));
    gets(&[GL_SCISSOR_TEST], server(GL_SCISSOR_BIT | GL_ENABLE_BIT));
    gets(
        &[GL_SAMPLE_COVERAGE_VALUE, GL_SAMPLE_COVERAGE_INVERT],
        server(GL_MULTISAMPLE_BIT),
    );
    gets(
        &[
            GL_MULTISAMPLE,
            GL_SAMPLE_ALPHA_TO_COVERAGE,
            GL_SAMPLE_ALPHA_TO_ONE,
            GL_SAMPLE_COVERAGE,
        ],
        server(GL_MULTISAMPLE_BIT | GL_ENABLE_BIT),
    );
    gets(&[GL_AUTO_NORMAL], server(GL_EVAL_BIT | GL_ENABLE_BIT));
    let maps: Vec<GLenum> = (GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4)
        .chain(GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4)
        .collect();
    gets(&maps, server(GL_EVAL_BIT | GL_ENABLE_BIT));
    gets(
        &[
            GL_MAP1_GRID_DOMAIN,
            GL_MAP1_GRID_SEGMENTS,
            GL_MAP2_GRID_DOMAIN,
            GL_MAP2_GRID_SEGMENTS,
        ],
        server(GL_EVAL_BIT),
    );
    gets(&[GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX], Bits::None);
    gets(&PIXEL_STORE_PNAMES, Bits::Client(GL_CLIENT_PIXEL_STORE_BIT));
    gets(&ARRAY_PNAMES, Bits::Client(GL_CLIENT_VERTEX_ARRAY_BIT));
    items.push(Item {
        name: "imaging scales, biases and borders".into(),
        bits: server(GL_PIXEL_MODE_BIT),
        read: Box::new(|ctx| {
            let mut read = String::new();
            for table in [GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE] {
                for pname in [GL_COLOR_TABLE_SCALE, GL_COLOR_TABLE_BIAS] {
                    read += &format!("{:?}", ctx.get_color_table_parameter(table, pname));
                }
            }
            for filter in [GL_CONVOLUTION_1D, GL_SEPARABLE_2D] {
                for pname in [
                    GL_CONVOLUTION_BORDER_MODE,
                    GL_CONVOLUTION_BORDER_COLOR,
                    GL_CONVOLUTION_FILTER_SCALE,
                    GL_CONVOLUTION_FILTER_BIAS,
                ] {
                    read += &format!("{:?}", ctx.get_convolution_parameter(filter, pname));
                }
            }
            read
        }),
    });
    for light in 0..8 {
        let light = GL_LIGHT0 + light;
        items.push(get(light, server(GL_LIGHTING_BIT | GL_ENABLE_BIT)));
        for pname in LIGHT_PNAMES {
            items.push(Item {
                name: format!("glGetLight 0x{light:04X} 0x{pname:04X}"),
                bits: server(GL_LIGHTING_BIT),
                read: Box::new(move |ctx| format!("{:?}", ctx.get_light(light, pname))),
            });
        }
    }
    for face in [GL_FRONT, GL_BACK] {
        for pname in MATERIAL_PNAMES {
            items.push(Item {
                name: format!("glGetMaterial 0x{face:04X} 0x{pname:04X}"),
                bits: server(GL_LIGHTING_BIT),
                read: Box::new(move |ctx| format!("{:?}", ctx.get_material(face, pname))),
            });
        }
    }
    for plane in GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 6 {
        items.push(get(plane, server(GL_TRANSFORM_BIT | GL_ENABLE_BIT)));
        items.push(Item {
            name: format!("glGetClipPlane 0x{plane:04X}"),
            bits: server(GL_TRANSFORM_BIT),
            read: Box::new(move |ctx| format!("{:?}", ctx.get_clip_plane(plane))),
        });
    }
    for unit in 0..MAX_TEXTURE_UNITS as GLenum {
        items.push(texture_unit_item(
            unit,
            &[GL_CURRENT_TEXTURE_COORDS, GL_CURRENT_RASTER_TEXTURE_COORDS],
            server(GL_CURRENT_BIT),
        ));
        items.push(texture_unit_item(unit, &[GL_TEXTURE_MATRIX], Bits::None));
        items.push(texture_unit_item(
            unit,
            TEXTURE_CAPABILITIES,
            server(GL_TEXTURE_BIT | GL_ENABLE_BIT),
        ));
        items.push(Item {
            name: format!("texture unit {unit}: coordinate generation"),
            bits: server(GL_TEXTURE_BIT),
            read: Box::new(move |ctx| {
                let mut probe = ctx.clone();
                probe.active_texture(GL_TEXTURE0 + unit).unwrap();
                let mut read = String::new();
                for coord in [GL_S, GL_T, GL_R, GL_Q] {
                    for pname in [GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE] {
                        read += &format!("{:?}", probe.get_tex_gen(coord, pname));
                    }
                }
                read
            }),
        });
        items.push(Item {
            name: format!("client texture unit {unit}: texture coordinate array"),
            bits: Bits::Client(GL_CLIENT_VERTEX_ARRAY_BIT),
            read: Box::new(move |ctx| {
                let mut probe = ctx.clone();
                probe.client_active_texture(GL_TEXTURE0 + unit).unwrap();
                format!("{:?}", TEX_COORD_ARRAY_PNAMES.map(|p| probe.get(p)))
            }),
        });
        items.push(texture_unit_item(
            unit,
            &TEXTURE_TARGETS,
            server(GL_TEXTURE_BIT | GL_ENABLE_BIT),
        ));
        items.push(texture_unit_item(
            unit,
            &TEXTURE_UNIT_PNAMES,
            server(GL_TEXTURE_BIT),
        ));
        items.push(Item {
            name: format!("texture unit {unit}: environment, bound objects' parameters"),
            bits: server(GL_TEXTURE_BIT),
            read: Box::new(move |ctx| {
                let mut probe = ctx.clone();
                probe.active_texture(GL_TEXTURE0 + unit).unwrap();
                let mut read = format!(
                    "{:?}",
                    probe.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE)
                );
                read += &format!(
                    "{:?}",
                    probe.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR)
                );
                for target in TEXTURE_TARGETS {
                    for pname in [
                        GL_TEXTURE_MIN_FILTER,
                        GL_TEXTURE_WRAP_S,
                        GL_TEXTURE_BORDER_COLOR,
                        GL_TEXTURE_PRIORITY,
                    ] {
                        read += &format!("{:?}", probe.get_tex_parameter(target, pname));
                    }
                }
                read
            }),
        });
    }
    items.push(Item {
        name: "glGetPolygonStipple".into(),
        bits: server(GL_POLYGON_STIPPLE_BIT),
        read: Box::new(|ctx| {
            // Packed with the initial pack modes, whatever the context's are.
            let mut probe = ctx.clone();
            probe.pop_client_attrib().ok();
            for pname in PIXEL_STORE_PNAMES {
                let initial = Context::new().get(pname).unwrap().as_ints()[0];
                probe.pixel_store(pname, StoreParam::Int(initial)).unwrap();
            }
            let mut bytes = vec![0; 128];
            probe.get_polygon_stipple(&mut bytes).unwrap();
            format!("{bytes:?}")
        }),
    });
    for map in PIXEL_MAPS {
        items.push(Item {
            name: format!("glGetPixelMap 0x{map:04X}"),
            bits: Bits::None,
            read: Box::new(move |ctx| format!("{:?}", ctx.get_pixel_map(map))),
        });
    }
    items
}

fn set_texture_parameters(ctx: &mut Context, target: GLenum, k: u32) {
    let f = k as f32;
    let pick = |a: GLenum, b: GLenum| if k % 2 == 1 { a } else { b };
    ctx.tex_parameter(
        target,
        GL_TEXTURE_MIN_FILTER,
        &[pick(GL_NEAREST, GL_LINEAR) as f32],
    )
    .unwrap();
    ctx.tex_parameter(
        target,
        GL_TEXTURE_WRAP_S,
        &[pick(GL_CLAMP, GL_REPEAT) as f32],
    )
    .unwrap();
    ctx.tex_parameter(target, GL_TEXTURE_BORDER_COLOR, &[0.1 * f, 0.2, 0.3, 0.4])
        .unwrap();
    ctx.tex_parameter(target, GL_TEXTURE_PRIORITY, &[0.25 * f])
        .unwrap();
}

const TEX_COORD_ARRAY_PNAMES: [GLenum; 5] = [
    GL_TEXTURE_COORD_ARRAY,
    GL_TEXTURE_COORD_ARRAY_SIZE,
    GL_TEXTURE_COORD_ARRAY_TYPE,
    GL_TEXTURE_COORD_ARRAY_STRIDE,
    GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
];

const TEXTURE_TARGETS: [GLenum; 4] = [
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
];
const TEXTURE_UNIT_PNAMES: [GLenum; 4] = [
    GL_TEXTURE_BINDING_1D,
    GL_TEXTURE_BINDING_2D,
    GL_TEXTURE_BINDING_3D,
    GL_TEXTURE_BINDING_CUBE_MAP,
];

/// glGet of `pnames` on texture unit `unit`, whichever unit is active.
fn texture_unit_item(unit: GLenum, pnames: &'static [GLenum], bits: Bits) -> Item {
    Item {
        name: format!("texture unit {unit}: glGet {pnames:04X?}"),
        bits,
        read: Box::new(move |ctx| {
            let mut probe = ctx.clone();
            probe.active_texture(GL_TEXTURE0 + unit).unwrap();
            format!(
                "{:?}",
                pnames.iter().map(|&p| probe.get(p)).collect::<Vec<_>>()
            )
        }),
    }
}

const LIGHT_PNAMES: [GLenum; 10] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_POSITION,
    GL_SPOT_DIRECTION,
    GL_SPOT_EXPONENT,
    GL_SPOT_CUTOFF,
    GL_CONSTANT_ATTENUATION,
    GL_LINEAR_ATTENUATION,
    GL_QUADRATIC_ATTENUATION,
];
const MATERIAL_PNAMES: [GLenum; 6] = [
    GL_AMBIENT,
    GL_DIFFUSE,
    GL_SPECULAR,
    GL_EMISSION,
    GL_SHININESS,
    GL_COLOR_INDEXES,
];
const ARRAY_PNAMES: [GLenum; 31] = [
    GL_SECONDARY_COLOR_ARRAY,
    GL_FOG_COORD_ARRAY,
    GL_SECONDARY_COLOR_ARRAY_TYPE,
    GL_SECONDARY_COLOR_ARRAY_STRIDE,
    GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING,
    GL_FOG_COORD_ARRAY_TYPE,
    GL_FOG_COORD_ARRAY_STRIDE,
    GL_FOG_COORD_ARRAY_BUFFER_BINDING,
    GL_INDEX_ARRAY_TYPE,
    GL_INDEX_ARRAY_STRIDE,
    GL_INDEX_ARRAY_BUFFER_BINDING,
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,
    GL_EDGE_FLAG_ARRAY,
    GL_VERTEX_ARRAY_SIZE,
    GL_VERTEX_ARRAY_TYPE,
    GL_VERTEX_ARRAY_STRIDE,
    GL_NORMAL_ARRAY_TYPE,
    GL_NORMAL_ARRAY_STRIDE,
    GL_COLOR_ARRAY_SIZE,
    GL_COLOR_ARRAY_TYPE,
    GL_COLOR_ARRAY_STRIDE,
    GL_EDGE_FLAG_ARRAY_STRIDE,
    GL_ARRAY_BUFFER_BINDING,
    GL_ELEMENT_ARRAY_BUFFER_BINDING,
    GL_VERTEX_ARRAY_BUFFER_BINDING,
    GL_NORMAL_ARRAY_BUFFER_BINDING,
    GL_COLOR_ARRAY_BUFFER_BINDING,
    GL_EDGE_FLAG_ARRAY_BUFFER_BINDING,
];

/// Sets every state of `items()` to values that depend on `k` (1 or 2): the two settings
/// differ in every item (checked by `the_two_settings_differ_everywhere`).
fn set_everything(ctx: &mut Context, k: u32) {
    let f = k as f32;
    let odd = k % 2 == 1;
    let pick = |a: GLenum, b: GLenum| if odd { a } else { b };
    let v = |x: f32| Vec4::new(0.1 * f, 0.2 * f, 0.3 * f, 0.4 * f) + Vec4::splat(x);
    // Current values and the raster position (a lit position: lighting is set below).
    ctx.color(v(0.0));
    ctx.normal(Vec3::new(0.1 * f, 0.5, 0.7));
    ctx.tex_coord(v(1.0));
    ctx.edge_flag(!odd);
    ctx.secondary_color([0.1 * f, 0.2, 0.3]);
    ctx.fog_coord(f);
    ctx.index(2.0 * f);
    ctx.list_base(10 * k).unwrap();
    for table in [GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE] {
        ctx.color_table_parameter(table, GL_COLOR_TABLE_SCALE, &[f, 2.0, 3.0, 4.0])
            .unwrap();
        ctx.color_table_parameter(table, GL_COLOR_TABLE_BIAS, &[0.0, f, 0.5, 0.25])
            .unwrap();
    }
    for filter in [GL_CONVOLUTION_1D, GL_SEPARABLE_2D] {
        let mode = pick(GL_CONSTANT_BORDER, GL_REPLICATE_BORDER) as f32;
        ctx.convolution_parameter(filter, GL_CONVOLUTION_BORDER_MODE, &[mode], false)
            .unwrap();
        for pname in [
            GL_CONVOLUTION_BORDER_COLOR,
            GL_CONVOLUTION_FILTER_SCALE,
            GL_CONVOLUTION_FILTER_BIAS,
        ] {
            ctx.convolution_parameter(filter, pname, &[f, 0.5, 0.25, 1.0], true)
                .unwrap();
        }
    }
    ctx.map_grid(1, [k as i32, 1], [f as f64, 3.0, 0.0, 1.0])
        .unwrap();
    ctx.map_grid(2, [k as i32, 2 * k as i32], [0.0, f as f64, -1.0, f as f64])
        .unwrap();
    // Textures: objects bound on every unit (new names in each setting), their parameters,
    // each unit's environment and enables, then the active unit.
    let mut names = [0; 4 * MAX_TEXTURE_UNITS];
    ctx.gen_textures(names.len() as i32, &mut names).unwrap();
    for unit in 0..MAX_TEXTURE_UNITS {
        ctx.active_texture(GL_TEXTURE0 + unit as GLenum).unwrap();
        for (t, &target) in TEXTURE_TARGETS.iter().enumerate() {
            // The default objects' parameters, then a new object's, except on unit 0 in the
            // first setting: the default objects stay bound there.
            ctx.bind_texture(target, 0).unwrap();
            set_texture_parameters(ctx, target, k);
            if unit != 0 || !odd {
                ctx.bind_texture(target, names[4 * unit + t]).unwrap();
                set_texture_parameters(ctx, target, k);
            }
            ctx.set_capability(target, (unit + t + k as usize).is_multiple_of(2))
                .unwrap();
        }
        let unit_f = unit as f32;
        ctx.multi_tex_coord(GL_TEXTURE0 + unit as GLenum, v(unit_f))
            .unwrap();
        let mode = [GL_OBJECT_LINEAR, GL_EYE_LINEAR][(unit + k as usize) % 2];
        for (c, coord) in [GL_S, GL_T, GL_R, GL_Q].into_iter().enumerate() {
            let enable = (unit + c + k as usize).is_multiple_of(2);
            ctx.set_capability(GL_TEXTURE_GEN_S + c as GLenum, enable)
                .unwrap();
            ctx.tex_gen(coord, GL_TEXTURE_GEN_MODE, &[mode as f64])
                .unwrap();
            let plane = [f, unit_f, coord as f32, 1.0];
            ctx.tex_gen(coord, GL_OBJECT_PLANE, &plane).unwrap();
            ctx.tex_gen(coord, GL_EYE_PLANE, &plane).unwrap();
        }
        ctx.tex_env(
            GL_TEXTURE_ENV,
            GL_TEXTURE_ENV_MODE,
            &[pick(GL_DECAL, GL_BLEND) as f32],
        )
        .unwrap();
        ctx.tex_env(
            GL_TEXTURE_ENV,
            GL_TEXTURE_ENV_COLOR,
            &[0.1 * f, 0.2, 0.3, 0.4],
        )
        .unwrap();
    }
    // Points, lines, polygons.
    ctx.point_size(f).unwrap();
    ctx.point_parameter(GL_POINT_SIZE_MIN, &[f]).unwrap();
    ctx.point_parameter(GL_POINT_SIZE_MAX, &[10.0 * f]).unwrap();
    ctx.point_parameter(GL_POINT_FADE_THRESHOLD_SIZE, &[2.0 * f])
        .unwrap();
    ctx.point_parameter(GL_POINT_DISTANCE_ATTENUATION, &[f, 2.0, 3.0])
        .unwrap();
    ctx.line_width(f + 0.5).unwrap();
    ctx.line_stipple(k as i32 + 2, 0x0F0F * k as u16).unwrap();
    ctx.cull_face(pick(GL_FRONT, GL_FRONT_AND_BACK)).unwrap();
    ctx.front_face(pick(GL_CW, GL_CCW)).unwrap();
    ctx.polygon_mode(GL_FRONT, pick(GL_LINE, GL_POINT)).unwrap();
    ctx.polygon_mode(GL_BACK, pick(GL_POINT, GL_LINE)).unwrap();
    ctx.polygon_offset(f, -f).unwrap();
    let stipple: Vec<u8> = (0..128).map(|i| (i * k) as u8).collect();
    ctx.polygon_stipple(&stipple).unwrap();
    // Pixels.
    for (i, &pname) in PIXEL_TRANSFER_PNAMES.iter().enumerate() {
        ctx.pixel_transfer(pname, if i < 2 { (k - 1) as f32 } else { f + i as f32 })
            .unwrap();
    }
    ctx.pixel_zoom(f, 2.0 * f).unwrap();
    ctx.read_buffer(pick(GL_LEFT, GL_FRONT_LEFT)).unwrap();
    for (i, map) in PIXEL_MAPS.into_iter().enumerate() {
        let size = 2 * k as i32;
        ctx.pixel_map(map, size, &vec![0.1 * f + 0.01 * i as f32; size as usize])
            .unwrap();
    }
    // Lighting.
    // Dim colors, so that the lit raster color is not clamped to the same white.
    let dim = |x: f32| (v(0.0) * x).to_array();
    for light in 0..8u32 {
        let l = GL_LIGHT0 + light;
        let s = f + light as f32;
        let d = 0.01 * (light + 1) as f32;
        ctx.light(l, GL_AMBIENT, &dim(d)).unwrap();
        ctx.light(l, GL_DIFFUSE, &dim(2.0 * d)).unwrap();
        ctx.light(l, GL_SPECULAR, &dim(3.0 * d)).unwrap();
        ctx.light(l, GL_POSITION, &[s, 1.0, 2.0, 1.0]).unwrap();
        ctx.light(l, GL_SPOT_DIRECTION, &[0.0, s, -1.0]).unwrap();
        ctx.light_scalar(l, GL_SPOT_EXPONENT, s).unwrap();
        ctx.light_scalar(l, GL_SPOT_CUTOFF, 40.0 + s).unwrap();
        ctx.light_scalar(l, GL_CONSTANT_ATTENUATION, s).unwrap();
        ctx.light_scalar(l, GL_LINEAR_ATTENUATION, s * 0.1).unwrap();
        ctx.light_scalar(l, GL_QUADRATIC_ATTENUATION, s * 0.01)
            .unwrap();
    }
    for (face, base) in [(GL_FRONT, 0.1), (GL_BACK, 0.2)] {
        ctx.material(face, GL_AMBIENT, &dim(base)).unwrap();
        ctx.material(face, GL_DIFFUSE, &dim(base + 0.1)).unwrap();
        ctx.material(face, GL_SPECULAR, &dim(base + 0.2)).unwrap();
        ctx.material(face, GL_EMISSION, &dim(base + 0.3)).unwrap();
        ctx.material_scalar(face, GL_SHININESS, f + base).unwrap();
        ctx.material(face, GL_COLOR_INDEXES, &[f, 2.0 * f, 3.0 * f])
            .unwrap();
    }
    ctx.light_model(GL_LIGHT_MODEL_AMBIENT, &dim(0.2)).unwrap();
    ctx.light_model_scalar(GL_LIGHT_MODEL_LOCAL_VIEWER, (k - 1) as f32)
        .unwrap();
    ctx.light_model_scalar(GL_LIGHT_MODEL_TWO_SIDE, (k - 1) as f32)
        .unwrap();
    let control = pick(GL_SEPARATE_SPECULAR_COLOR, GL_SINGLE_COLOR);
    ctx.light_model_scalar(GL_LIGHT_MODEL_COLOR_CONTROL, control as f32)
        .unwrap();
    ctx.color_material(pick(GL_BACK, GL_FRONT), pick(GL_EMISSION, GL_SPECULAR))
        .unwrap();
    ctx.shade_model(pick(GL_FLAT, GL_SMOOTH)).unwrap();
    // Fog, per-fragment operations, framebuffer control.
    ctx.fog(GL_FOG_COLOR, &v(0.0).to_array()).unwrap();
    ctx.fog_scalar(GL_FOG_INDEX, f).unwrap();
    ctx.fog_scalar(GL_FOG_DENSITY, f).unwrap();
    ctx.fog_scalar(GL_FOG_START, f).unwrap();
    ctx.fog_scalar(GL_FOG_END, 10.0 * f).unwrap();
    ctx.fog_scalar(GL_FOG_MODE, pick(GL_LINEAR, GL_EXP2) as f32)
        .unwrap();
    ctx.fog_scalar(
        GL_FOG_COORD_SRC,
        pick(GL_FOG_COORD, GL_FRAGMENT_DEPTH) as f32,
    )
    .unwrap();
    ctx.depth_func(pick(GL_GREATER, GL_EQUAL)).unwrap();
    ctx.clear_depth(0.25 * f as f64).unwrap();
    ctx.depth_mask(!odd).unwrap();
    ctx.clear_accum(v(-0.5)).unwrap();
    ctx.stencil_func(pick(GL_NEVER, GL_LEQUAL), k as i32, 0xF0 + k)
        .unwrap();
    ctx.stencil_op(
        pick(GL_ZERO, GL_INVERT),
        pick(GL_INCR, GL_DECR),
        pick(GL_REPLACE, GL_INCR_WRAP),
    )
    .unwrap();
    ctx.clear_stencil(k as i32).unwrap();
    ctx.stencil_mask(k).unwrap();
    ctx.viewport(k as i32, 2 * k as i32, 30 * k as i32, 40 * k as i32)
        .unwrap();
    ctx.depth_range(0.1 * f as f64, 0.3 * f as f64).unwrap();
    ctx.alpha_func(pick(GL_LESS, GL_GEQUAL), 0.25 * f).unwrap();
    ctx.blend_func_separate(
        pick(GL_SRC_COLOR, GL_DST_COLOR),
        pick(GL_SRC_ALPHA, GL_DST_ALPHA),
        pick(GL_CONSTANT_COLOR, GL_CONSTANT_ALPHA),
        pick(GL_ONE_MINUS_SRC_COLOR, GL_ONE_MINUS_DST_COLOR),
    )
    .unwrap();
    ctx.blend_equation(pick(GL_FUNC_SUBTRACT, GL_MAX)).unwrap();
    ctx.blend_color(v(0.0)).unwrap();
    ctx.logic_op(pick(GL_AND, GL_XOR)).unwrap();
    ctx.draw_buffer(pick(GL_NONE, GL_FRONT_AND_BACK)).unwrap();
    ctx.index_mask(k).unwrap();
    ctx.color_mask([odd, !odd, odd, !odd]).unwrap();
    ctx.clear_color(v(0.1)).unwrap();
    ctx.clear_index(f).unwrap();
    for (i, target) in HINT_TARGETS.into_iter().enumerate() {
        ctx.hint(target, [GL_FASTEST, GL_NICEST][(i + k as usize) % 2])
            .unwrap();
    }
    ctx.scissor(k as i32, 3, 4 * k as i32, 5).unwrap();
    ctx.sample_coverage(0.25 * f, odd).unwrap();
    // Transformation state: clip planes under an identity modelview, then the mode.
    for (i, plane) in (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 6).enumerate() {
        ctx.clip_plane(plane, [f as f64, i as f64, 1.0, 10.0])
            .unwrap();
    }
    ctx.matrix_mode(GL_PROJECTION).unwrap();
    ctx.scale(1.0 + 0.1 * f as f64, 1.0, 1.0).unwrap();
    ctx.matrix_mode(GL_TEXTURE).unwrap();
    for unit in 0..MAX_TEXTURE_UNITS as GLenum {
        ctx.active_texture(GL_TEXTURE0 + unit).unwrap();
        ctx.scale(f as f64, 1.0 + unit as f64, 1.0).unwrap();
    }
    ctx.matrix_mode(GL_MODELVIEW).unwrap();
    ctx.rotate(10.0 * f as f64, 0.0, 0.0, 1.0).unwrap();
    ctx.matrix_mode(pick(GL_TEXTURE, GL_PROJECTION)).unwrap();
    // Every capability: alternately on and off, shifted by k.
    let caps = ENABLE_BIT_CAPABILITIES.iter();
    for (i, &cap) in caps.enumerate() {
        ctx.set_capability(cap, (i + k as usize).is_multiple_of(2))
            .unwrap();
    }
    // (The texture targets' enables above were the last unit's.)
    ctx.active_texture(GL_TEXTURE0 + k).unwrap();
    // The raster position, with the state above: invalid in the first setting (its values
    // stay the initial ones), valid in the second.
    let x = if odd { 100.0 } else { 0.2 };
    ctx.raster_pos(Vec4::new(x, 0.2, -0.5, 1.0)).unwrap();
    // Client state.
    for (i, &pname) in PIXEL_STORE_PNAMES.iter().enumerate() {
        let value = match pname {
            GL_PACK_ALIGNMENT | GL_UNPACK_ALIGNMENT => 1 << k,
            GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST => (k - 1) as i32,
            GL_UNPACK_SWAP_BYTES | GL_UNPACK_LSB_FIRST => (k - 1) as i32,
            _ => (i as u32 + k) as i32,
        };
        ctx.pixel_store(pname, StoreParam::Int(value)).unwrap();
    }
    let buffers = ctx.gen_buffers(2).unwrap();
    let (array, element) = (buffers[0], buffers[1]);
    ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, element).unwrap();
    ctx.bind_buffer(GL_ARRAY_BUFFER, array).unwrap();
    let stride = 4 * k as i32;
    let address = 0x100 * k as usize;
    ctx.vertex_pointer(2 + k as i32 % 2, pick(GL_SHORT, GL_INT), stride, address)
        .unwrap();
    ctx.normal_pointer(pick(GL_BYTE, GL_SHORT), stride, address)
        .unwrap();
    ctx.bind_buffer(GL_ARRAY_BUFFER, if odd { array } else { 0 })
        .unwrap();
    ctx.color_pointer(
        3 + k as i32 % 2,
        pick(GL_UNSIGNED_BYTE, GL_DOUBLE),
        stride,
        address,
    )
    .unwrap();
    ctx.bind_buffer(GL_ARRAY_BUFFER, buffers[k as usize % 2])
        .unwrap();
    for unit in (0..MAX_TEXTURE_UNITS as GLenum).rev() {
        ctx.client_active_texture(GL_TEXTURE0 + unit).unwrap();
        let stride = stride + 4 * unit as i32;
        ctx.tex_coord_pointer(1 + k as i32 % 2, pick(GL_SHORT, GL_DOUBLE), stride, address)
            .unwrap();
        ctx.client_state(GL_TEXTURE_COORD_ARRAY, (unit + k).is_multiple_of(2))
            .unwrap();
    }
    ctx.edge_flag_pointer(stride, address).unwrap();
    ctx.secondary_color_pointer(3, pick(GL_BYTE, GL_FLOAT), stride + 4, address)
        .unwrap();
    ctx.fog_coord_pointer(pick(GL_FLOAT, GL_DOUBLE), stride + 8, address)
        .unwrap();
    ctx.index_pointer(pick(GL_SHORT, GL_INT), stride + 12, address)
        .unwrap();
    for (i, array) in CLIENT_ARRAYS.into_iter().enumerate() {
        ctx.client_state(array, (i + k as usize).is_multiple_of(2))
            .unwrap();
    }
    // (The texture coordinate array above was unit 0's.)
    ctx.client_active_texture(GL_TEXTURE0 + k).unwrap();
    // glGenBuffers counts up: the second setting's names differ from the first's.
}

const CLIENT_ARRAYS: [GLenum; 8] = [
    GL_SECONDARY_COLOR_ARRAY,
    GL_FOG_COORD_ARRAY,
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY,
];

const SERVER_BITS: [GLbitfield; 21] = [
    GL_CURRENT_BIT,
    GL_POINT_BIT,
    GL_LINE_BIT,
    GL_POLYGON_BIT,
    GL_POLYGON_STIPPLE_BIT,
    GL_PIXEL_MODE_BIT,
    GL_LIGHTING_BIT,
    GL_FOG_BIT,
    GL_DEPTH_BUFFER_BIT,
    GL_ACCUM_BUFFER_BIT,
    GL_STENCIL_BUFFER_BIT,
    GL_VIEWPORT_BIT,
    GL_TRANSFORM_BIT,
    GL_ENABLE_BIT,
    GL_COLOR_BUFFER_BIT,
    GL_HINT_BIT,
    GL_EVAL_BIT,
    GL_LIST_BIT,
    GL_TEXTURE_BIT,
    GL_SCISSOR_BIT,
    GL_MULTISAMPLE_BIT,
];

fn read_all(ctx: &Context, items: &[Item]) -> Vec<String> {
    items.iter().map(|item| (item.read)(ctx)).collect()
}

/// The states of setting 1, of setting 2, and after: setting 1, push, setting 2, pop.
fn push_change_pop(bits: Bits) -> [Vec<String>; 3] {
    let items = items();
    let mut first = Context::new();
    set_everything(&mut first, 1);
    let mut second = first.clone();
    set_everything(&mut second, 2);
    let mut ctx = first.clone();
    match bits {
        Bits::Server(mask) => ctx.push_attrib(mask).unwrap(),
        Bits::Client(mask) => ctx.push_client_attrib(mask).unwrap(),
        Bits::None => {}
    }
    set_everything(&mut ctx, 2);
    match bits {
        Bits::Server(_) => ctx.pop_attrib().unwrap(),
        Bits::Client(_) => ctx.pop_client_attrib().unwrap(),
        Bits::None => {}
    }
    [
        read_all(&first, &items),
        read_all(&second, &items),
        read_all(&ctx, &items),
    ]
}

/// Whether popping `popped` restores an item saved under `item`.
fn covers(popped: Bits, item: Bits) -> bool {
    match (popped, item) {
        (Bits::Server(p), Bits::Server(i)) => p & i != 0,
        (Bits::Client(p), Bits::Client(i)) => p & i != 0,
        _ => false,
    }
}

/// Pops `bits` and checks every item: restored exactly when one of its bits was pushed.
fn check_bits(bits: Bits) {
    let [first, second, after] = push_change_pop(bits);
    let mut failures = Vec::new();
    for (i, item) in items().iter().enumerate() {
        let restored = covers(bits, item.bits);
        let expected = if restored { &first[i] } else { &second[i] };
        // Color material tracks the current color: with it enabled, the material it
        // tracks follows the current color restored or not (checked on its own below).
        if item.name.starts_with("glGetMaterial") {
            continue;
        }
        if &after[i] != expected {
            failures.push(format!(
                "{} (restored: {restored}): {} instead of {expected}",
                item.name, after[i]
            ));
        }
    }
    assert!(failures.is_empty(), "{bits:?}:\n{}", failures.join("\n"));
}

#[test]
fn the_two_settings_differ_everywhere() {
    let [first, second, _] = push_change_pop(Bits::None);
    for (i, item) in items().iter().enumerate() {
        assert_ne!(
            first[i], second[i],
            "{} is the same in both settings",
            item.name
        );
        assert!(!first[i].contains("Err"), "{}: {}", item.name, first[i]);
    }
}

#[test]
fn each_server_bit_restores_its_state_and_no_other() {
    for bit in SERVER_BITS {
        check_bits(Bits::Server(bit));
    }
}

#[test]
fn all_attrib_bits_restore_every_server_state() {
    check_bits(Bits::Server(GL_ALL_ATTRIB_BITS));
    check_bits(Bits::Server(GL_LIGHTING_BIT | GL_FOG_BIT | GL_VIEWPORT_BIT));
    check_bits(Bits::Server(0));
}

#[test]
fn each_client_bit_restores_its_state_and_no_other() {
    for bit in [
        GL_CLIENT_PIXEL_STORE_BIT,
        GL_CLIENT_VERTEX_ARRAY_BIT,
        GL_CLIENT_ALL_ATTRIB_BITS,
        0,
    ] {
        check_bits(Bits::Client(bit));
    }
}

#[test]
fn materials_come_back_with_the_lighting_bit() {
    let mut ctx = Context::new();
    set_everything(&mut ctx, 1);
    ctx.set_capability(GL_COLOR_MATERIAL, false).unwrap();
    let saved: Vec<_> = MATERIAL_PNAMES
        .iter()
        .map(|&p| ctx.get_material(GL_BACK, p))
        .collect();
    ctx.push_attrib(GL_LIGHTING_BIT).unwrap();
    set_everything(&mut ctx, 2);
    ctx.set_capability(GL_COLOR_MATERIAL, false).unwrap();
    ctx.pop_attrib().unwrap();
    let restored: Vec<_> = MATERIAL_PNAMES
        .iter()
        .map(|&p| ctx.get_material(GL_BACK, p))
        .collect();
    assert_eq!(restored, saved);
}

/// §2.14.3: while color material is enabled, the tracked properties are the current color,
/// also when a pop restores the current color (OSMesa keeps the last glColor there:
/// docs/osmesa-differences.md).
#[test]
fn color_material_tracks_the_restored_current_color() {
    let mut ctx = Context::new();
    ctx.set_capability(GL_COLOR_MATERIAL, true).unwrap();
    ctx.color(Vec4::new(0.9, 0.8, 0.7, 0.6));
    ctx.push_attrib(GL_CURRENT_BIT).unwrap();
    ctx.color(Vec4::new(0.1, 0.2, 0.3, 0.4));
    ctx.pop_attrib().unwrap();
    let (diffuse, _) = ctx.get_material(GL_FRONT, GL_DIFFUSE).unwrap();
    assert_eq!(diffuse, Vec4::new(0.9, 0.8, 0.7, 0.6));
    // Popping the lighting group brings the saved material back, then tracking applies.
    ctx.push_attrib(GL_LIGHTING_BIT).unwrap();
    ctx.color(Vec4::new(0.5, 0.5, 0.5, 0.5));
    ctx.pop_attrib().unwrap();
    let (diffuse, _) = ctx.get_material(GL_FRONT, GL_DIFFUSE).unwrap();
    assert_eq!(diffuse, Vec4::new(0.5, 0.5, 0.5, 0.5));
}

/// Restored lighting and transformation state reaches the vertices: the derived constants
/// are rebuilt.
#[test]
fn popped_state_lights_the_next_vertex() {
    let mut ctx = Context::new();
    ctx.set_capability(GL_LIGHTING, true).unwrap();
    ctx.set_capability(GL_LIGHT0, true).unwrap();
    let before = ctx.derived().lighting.clone();
    ctx.push_attrib(GL_LIGHTING_BIT).unwrap();
    ctx.light(GL_LIGHT0, GL_DIFFUSE, &[0.0, 1.0, 0.0, 1.0])
        .unwrap();
    let changed = ctx.derived().lighting.clone();
    ctx.pop_attrib().unwrap();
    assert_ne!(format!("{before:?}"), format!("{changed:?}"));
    assert_eq!(
        format!("{:?}", ctx.derived().lighting),
        format!("{before:?}")
    );
    ctx.push_attrib(GL_TRANSFORM_BIT).unwrap();
    ctx.set_capability(GL_NORMALIZE, true).unwrap();
    assert!(ctx.derived().transform.normalize);
    ctx.pop_attrib().unwrap();
    assert!(!ctx.derived().transform.normalize);
}

#[test]
fn stack_depths_overflow_underflow_and_begin_end() {
    let mut ctx = Context::new();
    assert_eq!(ctx.get(GL_MAX_ATTRIB_STACK_DEPTH).unwrap().as_ints(), [16]);
    assert_eq!(
        ctx.get(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH).unwrap().as_ints(),
        [16]
    );
    for depth in 1..=16 {
        ctx.push_attrib(GL_ALL_ATTRIB_BITS).unwrap();
        ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS).unwrap();
        assert_eq!(ctx.get(GL_ATTRIB_STACK_DEPTH).unwrap().as_ints(), [depth]);
        assert_eq!(
            ctx.get(GL_CLIENT_ATTRIB_STACK_DEPTH).unwrap().as_ints(),
            [depth]
        );
    }
    assert_eq!(ctx.push_attrib(0), Err(GlError::StackOverflow));
    assert_eq!(ctx.push_client_attrib(0), Err(GlError::StackOverflow));
    assert_eq!(ctx.attrib_stack_depth(), 16);
    assert_eq!(ctx.client_attrib_stack_depth(), 16);
    for _ in 0..16 {
        ctx.pop_attrib().unwrap();
        ctx.pop_client_attrib().unwrap();
    }
    assert_eq!(ctx.pop_attrib(), Err(GlError::StackUnderflow));
    assert_eq!(ctx.pop_client_attrib(), Err(GlError::StackUnderflow));
    ctx.push_attrib(GL_ALL_ATTRIB_BITS).unwrap();
    ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS).unwrap();
    ctx.begin(GL_POINTS).unwrap();
    for result in [
        ctx.push_attrib(GL_ALL_ATTRIB_BITS),
        ctx.pop_attrib(),
        ctx.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS),
        ctx.pop_client_attrib(),
    ] {
        assert_eq!(result, Err(GlError::InvalidOperation));
    }
    ctx.end().unwrap();
    assert_eq!(ctx.attrib_stack_depth(), 1);
    assert_eq!(ctx.client_attrib_stack_depth(), 1);
}

/// A buffer object deleted while its binding is saved comes back as binding 0 (§2.9: the
/// bindings to a deleted object revert to zero), even if the name is bound anew meanwhile.
#[test]
fn a_deleted_buffer_is_not_restored() {
    let mut ctx = Context::new();
    let names = ctx.gen_buffers(2).unwrap();
    ctx.bind_buffer(GL_ARRAY_BUFFER, names[0]).unwrap();
    ctx.vertex_pointer(3, GL_FLOAT, 0, 0).unwrap();
    ctx.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, names[1]).unwrap();
    ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT).unwrap();
    ctx.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT).unwrap();
    ctx.delete_buffers(&names[..1]).unwrap();
    ctx.bind_buffer(GL_ARRAY_BUFFER, names[0]).unwrap();
    ctx.pop_client_attrib().unwrap();
    let binding = |ctx: &Context, pname| ctx.get(pname).unwrap().as_ints()[0];
    assert_eq!(binding(&ctx, GL_ARRAY_BUFFER_BINDING), 0);
    assert_eq!(binding(&ctx, GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
    assert_eq!(
        binding(&ctx, GL_ELEMENT_ARRAY_BUFFER_BINDING),
        names[1] as i32
    );
    ctx.delete_buffers(&names[1..]).unwrap();
    ctx.pop_client_attrib().unwrap();
    assert_eq!(binding(&ctx, GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
    assert!(ctx.is_buffer(names[0]).unwrap());
    assert!(!ctx.is_buffer(names[1]).unwrap());
}

/// Every capability glIsEnabled accepts is in ENABLE_BIT_CAPABILITIES (so GL_ENABLE_BIT and the
/// tests above cover it, the client arrays aside), and no other.
#[test]
fn every_capability_is_listed() {
    let ctx = Context::new();
    let arrays = [
        GL_VERTEX_ARRAY,
        GL_NORMAL_ARRAY,
        GL_COLOR_ARRAY,
        GL_INDEX_ARRAY,
        GL_TEXTURE_COORD_ARRAY,
        GL_EDGE_FLAG_ARRAY,
        GL_SECONDARY_COLOR_ARRAY,
        GL_FOG_COORD_ARRAY,
    ];
    let accepted: Vec<GLenum> = (0..0x10000)
        .filter(|&cap| ctx.is_enabled(cap).is_ok() && !arrays.contains(&cap))
        .collect();
    let mut listed = ENABLE_BIT_CAPABILITIES.to_vec();
    listed.sort();
    assert_eq!(accepted, listed);
}
