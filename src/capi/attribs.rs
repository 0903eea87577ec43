//! Current vertex attributes and vertices: glColor, glNormal, glTexCoord, glEdgeFlag,
//! glVertex in every form (§2.7). Integer colors and normals are normalized (table 2.9);
//! vertex and texture coordinates convert directly.

use glam::{Vec3, Vec4};

use super::{quick, read, with_context};
use crate::commands::list::Command;
use crate::error::GlError;
use crate::gl::*;
use crate::state::convert::Component;

/// Runs `command`, or compiles it into the display list being compiled.
pub(super) fn record_or_run(command: Command) {
    with_context(|ctx| ctx.record_or_run(command))
}

/// The vertex attribute commands, the most frequent of all. Their usual case, `$usual` (an
/// expression of `ctx` that is whether it did the command), runs outside display list
/// compilation with no call, compiled into the entry point (`quick!`): immediate mode 1
/// light, median ratio 0.85 on one thread and 0.84 on two against the guard and a call per
/// command, then 0.89 and 0.90 with glVertex's usual case compiled in too. Every other case
/// goes out of line to `$general`, which compiles the command into the list or calls the
/// context: building, matching and dropping a `Command` (a large enum) outside a list cost
/// more than the command itself (immediate mode 100M -> 188M instructions for 100K
/// vertices). The components travel as separate arguments, in registers: through memory, a
/// vector read back just after being written as scalars waits for the stores (immediate
/// mode 1 light, 34 -> 23 ns/vertex).
macro_rules! attribute {
    (
        $name:ident, $lazy:ident([$($c:ident),+]; $n:literal) usually |$ctx:ident| $usual:expr;
        else $general:ident: $variant:ident($vector:ident) by $method:ident
    ) => {
        #[inline(always)]
        fn $name(components: [f32; $n]) {
            $lazy(|| components)
        }

        // The command, its components read only where used (after the checks of the
        // usual case): read first, they were kept on the stack across them.
        #[inline(always)]
        fn $lazy(components: impl Fn() -> [f32; $n]) {
            if !quick!(|$ctx| {
                let [$($c),+] = components();
                $usual
            }) {
                let [$($c),+] = components();
                $general($($c),+);
            }
        }

        #[inline(never)]
        fn $general($($c: f32),+) {
            with_context(move |ctx| {
                if ctx.compiling_list() {
                    compile(ctx, Command::$variant($vector::new($($c),+)))
                } else {
                    ctx.$method($($c),+);
                    Ok(())
                }
            })
        }
    };
}

/// A vertex attribute command while a display list is being compiled: out of the way of the
/// entry points' common path.
#[cold]
#[inline(never)]
fn compile(ctx: &mut crate::context::Context, command: Command) -> crate::error::GlResult {
    ctx.record_or_run(command)
}

attribute!(vertex, vertex_lazily([x, y, z, w]; 4) usually |ctx| ctx.try_vertex_quick(x, y, z, w);
    else any_vertex: Vertex(Vec4) by vertex_xyzw);
attribute!(color, color_lazily([r, g, b, a]; 4) usually |ctx| ctx.try_color_quick(r, g, b, a);
    else any_color: Color(Vec4) by color_rgba);
attribute!(normal, normal_lazily([x, y, z]; 3) usually |ctx| { ctx.normal_xyz(x, y, z); true };
    else any_normal: Normal(Vec3) by normal_xyz);
attribute!(tex_coord, tex_coord_lazily([s, t, r, q]; 4)
    usually |ctx| { ctx.tex_coord(Vec4::new(s, t, r, q)); true };
    else any_tex_coord: TexCoord(Vec4) by tex_coord_strq);

/// A NULL vector: GL_INVALID_VALUE, compiled too (the error is raised when the list
/// executes). Out of line, so that the entry points build no `Command` on their stack.
#[cold]
#[inline(never)]
fn null_vector() {
    record_or_run(Command::Error(GlError::InvalidValue));
}

/// Reads `N` components at `v` into a 4-vector padded with `pad`; NULL is GL_INVALID_VALUE.
///
/// # Safety
/// A non-NULL `v` must point to `N` readable values.
#[inline(always)]
pub(super) unsafe fn read_vector<T: Component, const N: usize>(
    v: *const T,
    pad: [f32; 4],
    convert: fn(T) -> f32,
    command: fn([f32; 4]),
) {
    // SAFETY: forwarded from the caller.
    let values = unsafe { read(v, N) };
    if values.is_empty() {
        null_vector();
        return;
    }
    let mut out = pad;
    for (o, &x) in out.iter_mut().zip(values) {
        *o = convert(x);
    }
    command(out);
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3b(r: GLbyte, g: GLbyte, b: GLbyte) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3bv(v: *const GLbyte) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLbyte, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3s(r: GLshort, g: GLshort, b: GLshort) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3i(r: GLint, g: GLint, b: GLint) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3f(r: GLfloat, g: GLfloat, b: GLfloat) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3d(r: GLdouble, g: GLdouble, b: GLdouble) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3ub(r: GLubyte, g: GLubyte, b: GLubyte) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3ubv(v: *const GLubyte) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLubyte, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3us(r: GLushort, g: GLushort, b: GLushort) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3usv(v: *const GLushort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLushort, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor3ui(r: GLuint, g: GLuint, b: GLuint) {
    color([r.normalized(), g.normalized(), b.normalized(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor3uiv(v: *const GLuint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLuint, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4b(r: GLbyte, g: GLbyte, b: GLbyte, a: GLbyte) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4bv(v: *const GLbyte) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLbyte, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4s(r: GLshort, g: GLshort, b: GLshort, a: GLshort) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4i(r: GLint, g: GLint, b: GLint, a: GLint) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4d(r: GLdouble, g: GLdouble, b: GLdouble, a: GLdouble) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4ub(r: GLubyte, g: GLubyte, b: GLubyte, a: GLubyte) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4ubv(v: *const GLubyte) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLubyte, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4us(r: GLushort, g: GLushort, b: GLushort, a: GLushort) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4usv(v: *const GLushort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLushort, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glColor4ui(r: GLuint, g: GLuint, b: GLuint, a: GLuint) {
    color([
        r.normalized(),
        g.normalized(),
        b.normalized(),
        a.normalized(),
    ])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glColor4uiv(v: *const GLuint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLuint, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::normalized, color) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glNormal3b(nx: GLbyte, ny: GLbyte, nz: GLbyte) {
    normal([nx.normalized(), ny.normalized(), nz.normalized()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glNormal3bv(v: *const GLbyte) {
    // SAFETY: forwarded from the caller.
    unsafe {
        read_vector::<GLbyte, 3>(v, [0.0; 4], Component::normalized, |n| {
            normal([n[0], n[1], n[2]])
        })
    }
}

#[unsafe(no_mangle)]
pub extern "C" fn glNormal3s(nx: GLshort, ny: GLshort, nz: GLshort) {
    normal([nx.normalized(), ny.normalized(), nz.normalized()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glNormal3sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe {
        read_vector::<GLshort, 3>(v, [0.0; 4], Component::normalized, |n| {
            normal([n[0], n[1], n[2]])
        })
    }
}

#[unsafe(no_mangle)]
pub extern "C" fn glNormal3i(nx: GLint, ny: GLint, nz: GLint) {
    normal([nx.normalized(), ny.normalized(), nz.normalized()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glNormal3iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe {
        read_vector::<GLint, 3>(v, [0.0; 4], Component::normalized, |n| {
            normal([n[0], n[1], n[2]])
        })
    }
}

#[unsafe(no_mangle)]
pub extern "C" fn glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat) {
    normal([nx.normalized(), ny.normalized(), nz.normalized()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glNormal3fv(v: *const GLfloat) {
    if v.is_null() {
        return null_vector();
    }
    // SAFETY: the caller guarantees 3 readable values at a non-NULL `v`.
    normal_lazily(|| unsafe { [*v, *v.add(1), *v.add(2)] })
}

#[unsafe(no_mangle)]
pub extern "C" fn glNormal3d(nx: GLdouble, ny: GLdouble, nz: GLdouble) {
    normal([nx.normalized(), ny.normalized(), nz.normalized()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glNormal3dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe {
        read_vector::<GLdouble, 3>(v, [0.0; 4], Component::normalized, |n| {
            normal([n[0], n[1], n[2]])
        })
    }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord1s(s: GLshort) {
    tex_coord([s.direct(), 0.0, 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord1sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 1>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord1i(s: GLint) {
    tex_coord([s.direct(), 0.0, 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord1iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 1>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord1f(s: GLfloat) {
    tex_coord([s.direct(), 0.0, 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord1fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 1>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord1d(s: GLdouble) {
    tex_coord([s.direct(), 0.0, 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord1dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 1>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord2s(s: GLshort, t: GLshort) {
    tex_coord([s.direct(), t.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord2sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord2i(s: GLint, t: GLint) {
    tex_coord([s.direct(), t.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord2iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord2f(s: GLfloat, t: GLfloat) {
    tex_coord([s.direct(), t.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord2fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord2d(s: GLdouble, t: GLdouble) {
    tex_coord([s.direct(), t.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord2dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord3s(s: GLshort, t: GLshort, r: GLshort) {
    tex_coord([s.direct(), t.direct(), r.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord3sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord3i(s: GLint, t: GLint, r: GLint) {
    tex_coord([s.direct(), t.direct(), r.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord3iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat) {
    tex_coord([s.direct(), t.direct(), r.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord3fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble) {
    tex_coord([s.direct(), t.direct(), r.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord3dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
    tex_coord([s.direct(), t.direct(), r.direct(), q.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord4sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint) {
    tex_coord([s.direct(), t.direct(), r.direct(), q.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord4iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
    tex_coord([s.direct(), t.direct(), r.direct(), q.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord4fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
    tex_coord([s.direct(), t.direct(), r.direct(), q.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glTexCoord4dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, tex_coord) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex2s(x: GLshort, y: GLshort) {
    vertex([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex2sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex2i(x: GLint, y: GLint) {
    vertex([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex2iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex2f(x: GLfloat, y: GLfloat) {
    vertex([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex2fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex2d(x: GLdouble, y: GLdouble) {
    vertex([x.direct(), y.direct(), 0.0, 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex2dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 2>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex3s(x: GLshort, y: GLshort, z: GLshort) {
    vertex([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex3sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex3i(x: GLint, y: GLint, z: GLint) {
    vertex([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex3iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    vertex([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex3fv(v: *const GLfloat) {
    if v.is_null() {
        return null_vector();
    }
    // SAFETY: the caller guarantees 3 readable values at a non-NULL `v`.
    vertex_lazily(|| unsafe { [*v, *v.add(1), *v.add(2), 1.0] })
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    vertex([x.direct(), y.direct(), z.direct(), 1.0])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex3dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 3>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    vertex([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex4sv(v: *const GLshort) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLshort, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    vertex([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex4iv(v: *const GLint) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLint, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    vertex([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex4fv(v: *const GLfloat) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLfloat, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glVertex4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    vertex([x.direct(), y.direct(), z.direct(), w.direct()])
}

/// # Safety
/// `v` is NULL or points to the values the command reads.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glVertex4dv(v: *const GLdouble) {
    // SAFETY: forwarded from the caller.
    unsafe { read_vector::<GLdouble, 4>(v, [0.0, 0.0, 0.0, 1.0], Component::direct, vertex) }
}

#[unsafe(no_mangle)]
pub extern "C" fn glEdgeFlag(flag: GLboolean) {
    record_or_run(Command::EdgeFlag(flag != 0))
}

/// # Safety
/// `flag` is NULL or points to one GLboolean.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn glEdgeFlagv(flag: *const GLboolean) {
    // SAFETY: forwarded from the caller.
    let values = unsafe { read(flag, 1) };
    record_or_run(
        values
            .first()
            .map_or(Command::Error(GlError::InvalidValue), |&flag| {
                Command::EdgeFlag(flag != 0)
            }),
    )
}
