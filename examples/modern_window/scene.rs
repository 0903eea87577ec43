//! The legacy routine: a lit scene written as OpenGL 1.x programs draw one, with lights,
//! materials, color material, glBegin/glEnd, vertex arrays, a display list and two-sided
//! lighting. It calls GL
//! only through the [`Legacy`] table it is given and does not know whose GL that is: fflight
//! (captured) or the system GL's fixed-function pipeline.
//!
//! Every object gets its own alpha (the diffuse alpha, or the color array's for the color
//! material sphere), so the alpha channel of a rendering tells which object covers a pixel:
//! `compare.rs` finds the silhouettes with it.

use std::f32::consts::PI;
use std::ffi::c_void;

use crate::gl::*;

/// Alpha of each object: the clear color's, the floor's, the vertex-array sphere's, the two
/// display-list spheres', the tube's outside (front faces) and inside (back faces). Multiples
/// of 1/255, so that both GLs store exactly k in RGBA8 (a value halfway between two steps
/// could round either way).
pub const OBJECT_ALPHAS: [f32; 7] = [
    0.0,
    96.0 / 255.0,
    160.0 / 255.0,
    224.0 / 255.0,
    1.0,
    192.0 / 255.0,
    128.0 / 255.0,
];

/// A sphere of `stacks` x `slices` quads around the origin, radius 1: positions (which are also
/// the normals), and a color per vertex.
struct Sphere {
    positions: Vec<[f32; 3]>,
    colors: Vec<[f32; 4]>,
    rows: usize,
    columns: usize,
}

impl Sphere {
    fn new(stacks: usize, slices: usize, alpha: f32) -> Sphere {
        let mut positions = Vec::new();
        let mut colors = Vec::new();
        for i in 0..=stacks {
            let theta = PI * i as f32 / stacks as f32;
            for j in 0..=slices {
                let phi = 2.0 * PI * j as f32 / slices as f32;
                let p = [
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                ];
                positions.push(p);
                colors.push([
                    0.5 + 0.5 * p[0],
                    0.5 + 0.5 * p[1],
                    0.5 - 0.5 * p[2] * p[0],
                    alpha,
                ]);
            }
        }
        Sphere {
            positions,
            colors,
            rows: stacks,
            columns: slices,
        }
    }

    fn index(&self, i: usize, j: usize) -> usize {
        i * (self.columns + 1) + j
    }

    /// Two counterclockwise (seen from outside) triangles per quad.
    fn triangle_indices(&self) -> Vec<u16> {
        let mut indices = Vec::new();
        for i in 0..self.rows {
            for j in 0..self.columns {
                let (a, b) = (self.index(i, j), self.index(i, j + 1));
                let (c, d) = (self.index(i + 1, j), self.index(i + 1, j + 1));
                for k in [a, b, c, b, d, c] {
                    indices.push(k as u16);
                }
            }
        }
        indices
    }
}

/// Draws the scene into a `width` x `height` viewport through `gl`.
///
/// # Safety
/// `gl` holds valid functions of a GL with a current context on this thread.
pub unsafe fn draw(gl: &Legacy, width: i32, height: i32) {
    unsafe {
        (gl.glViewport)(0, 0, width, height);
        (gl.glClearColor)(0.0, 0.0, 0.0, OBJECT_ALPHAS[0]);
        (gl.glClear)(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        (gl.glEnable)(GL_DEPTH_TEST);
        (gl.glDepthFunc)(GL_LESS);
        (gl.glFrontFace)(GL_CCW);
        (gl.glShadeModel)(GL_SMOOTH);

        let aspect = width as f64 / height as f64;
        (gl.glMatrixMode)(GL_PROJECTION);
        (gl.glLoadIdentity)();
        (gl.glFrustum)(-0.42 * aspect, 0.42 * aspect, -0.42, 0.42, 1.0, 30.0);
        (gl.glMatrixMode)(GL_MODELVIEW);
        (gl.glLoadIdentity)();
        (gl.glTranslatef)(0.0, -0.1, -5.8);
        (gl.glRotatef)(22.0, 1.0, 0.0, 0.0);
        (gl.glRotatef)(-12.0, 0.0, 1.0, 0.0);

        // Lights, placed in the world (after the viewing transform).
        let ambient = [0.16f32, 0.16, 0.2, 1.0];
        (gl.glLightModelfv)(GL_LIGHT_MODEL_AMBIENT, ambient.as_ptr());
        (gl.glLightModeli)(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        (gl.glLightModeli)(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_SEPARATE_SPECULAR_COLOR as i32,
        );
        (gl.glEnable)(GL_LIGHTING);
        (gl.glEnable)(GL_NORMALIZE);

        // A white directional key light.
        (gl.glLightfv)(GL_LIGHT0, GL_POSITION, [-0.5f32, 0.9, 0.7, 0.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT0, GL_DIFFUSE, [0.65f32, 0.65, 0.6, 1.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT0, GL_SPECULAR, [0.8f32, 0.8, 0.8, 1.0].as_ptr());
        (gl.glEnable)(GL_LIGHT0);
        // A warm point light with distance attenuation.
        (gl.glLightfv)(GL_LIGHT1, GL_POSITION, [1.8f32, 1.0, 1.4, 1.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT1, GL_DIFFUSE, [0.9f32, 0.45, 0.15, 1.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT1, GL_SPECULAR, [1.0f32, 0.6, 0.3, 1.0].as_ptr());
        (gl.glLightf)(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.5);
        (gl.glLightf)(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2);
        (gl.glLightf)(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05);
        (gl.glEnable)(GL_LIGHT1);
        // A blue spot light shining down on the floor.
        (gl.glLightfv)(GL_LIGHT2, GL_POSITION, [-0.2f32, 2.8, -0.4, 1.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT2, GL_SPOT_DIRECTION, [0.05f32, -1.0, 0.2].as_ptr());
        (gl.glLightf)(GL_LIGHT2, GL_SPOT_CUTOFF, 30.0);
        (gl.glLightf)(GL_LIGHT2, GL_SPOT_EXPONENT, 6.0);
        (gl.glLightfv)(GL_LIGHT2, GL_DIFFUSE, [0.25f32, 0.45, 1.0, 1.0].as_ptr());
        (gl.glLightfv)(GL_LIGHT2, GL_SPECULAR, [0.3f32, 0.5, 1.0, 1.0].as_ptr());
        (gl.glEnable)(GL_LIGHT2);

        // The floor: immediate mode quad strips, one normal for all.
        let floor = [0.55f32, 0.55, 0.5, OBJECT_ALPHAS[1]];
        (gl.glMaterialfv)(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, floor.as_ptr());
        (gl.glMaterialfv)(
            GL_FRONT_AND_BACK,
            GL_SPECULAR,
            [0.25f32, 0.25, 0.25, 1.0].as_ptr(),
        );
        (gl.glMaterialf)(GL_FRONT_AND_BACK, GL_SHININESS, 12.0);
        let cells = 48;
        let (x0, z0, width, depth) = (-6.0f32, -10.0f32, 12.0f32, 13.0f32);
        (gl.glNormal3f)(0.0, 1.0, 0.0);
        for i in 0..cells {
            let xa = x0 + width * i as f32 / cells as f32;
            let xb = x0 + width * (i + 1) as f32 / cells as f32;
            (gl.glBegin)(GL_QUAD_STRIP);
            for k in 0..=cells {
                let z = z0 + depth * k as f32 / cells as f32;
                (gl.glVertex3f)(xb, -1.0, z);
                (gl.glVertex3f)(xa, -1.0, z);
            }
            (gl.glEnd)();
        }

        // A sphere from vertex arrays, colored per vertex through color material.
        let sphere = Sphere::new(20, 32, OBJECT_ALPHAS[2]);
        let indices = sphere.triangle_indices();
        (gl.glColorMaterial)(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        (gl.glEnable)(GL_COLOR_MATERIAL);
        (gl.glMaterialfv)(
            GL_FRONT_AND_BACK,
            GL_SPECULAR,
            [0.6f32, 0.6, 0.6, 1.0].as_ptr(),
        );
        (gl.glMaterialf)(GL_FRONT_AND_BACK, GL_SHININESS, 40.0);
        let positions = sphere.positions.as_ptr().cast::<c_void>();
        (gl.glVertexPointer)(3, GL_FLOAT, 0, positions);
        (gl.glNormalPointer)(GL_FLOAT, 0, positions);
        (gl.glColorPointer)(4, GL_FLOAT, 0, sphere.colors.as_ptr().cast());
        (gl.glEnableClientState)(GL_VERTEX_ARRAY);
        (gl.glEnableClientState)(GL_NORMAL_ARRAY);
        (gl.glEnableClientState)(GL_COLOR_ARRAY);
        (gl.glPushMatrix)();
        (gl.glTranslatef)(-1.35, -0.15, 0.2);
        (gl.glScalef)(0.8, 0.8, 0.8);
        (gl.glDrawElements)(
            GL_TRIANGLES,
            indices.len() as i32,
            GL_UNSIGNED_SHORT,
            indices.as_ptr().cast(),
        );
        (gl.glPopMatrix)();
        (gl.glDisableClientState)(GL_COLOR_ARRAY);
        (gl.glDisableClientState)(GL_NORMAL_ARRAY);
        (gl.glDisableClientState)(GL_VERTEX_ARRAY);
        (gl.glDisable)(GL_COLOR_MATERIAL);

        // A display list of a sphere made of quad strips, called twice with different
        // materials and a non-uniform scale (GL_NORMALIZE renormalizes its normals).
        let shape = Sphere::new(16, 24, 1.0);
        let list = (gl.glGenLists)(1);
        (gl.glNewList)(list, GL_COMPILE);
        for i in 0..shape.rows {
            (gl.glBegin)(GL_QUAD_STRIP);
            for j in 0..=shape.columns {
                for p in [shape.index(i + 1, j), shape.index(i, j)] {
                    (gl.glNormal3fv)(shape.positions[p].as_ptr());
                    (gl.glVertex3fv)(shape.positions[p].as_ptr());
                }
            }
            (gl.glEnd)();
        }
        (gl.glEndList)();

        // Each instance: ambient, diffuse, emission, shininess; position, rotation about z,
        // scale.
        let instances = [
            (
                [0.6f32, 0.1, 0.1, 1.0],
                [0.85f32, 0.12, 0.1, OBJECT_ALPHAS[3]],
                [0.0f32, 0.0, 0.0, 1.0],
                64.0,
                [0.55f32, -0.35, 0.7],
                0.0,
                [0.65f32, 0.65, 0.65],
            ),
            (
                [0.1, 0.3, 0.15, 1.0],
                [0.2, 0.7, 0.3, OBJECT_ALPHAS[4]],
                [0.0, 0.05, 0.02, 1.0],
                16.0,
                [1.2, 0.1, -1.4],
                30.0,
                [1.3, 0.8, 0.8],
            ),
        ];
        (gl.glMaterialfv)(GL_FRONT, GL_SPECULAR, [0.9f32, 0.9, 0.9, 1.0].as_ptr());
        for (ambient, diffuse, emission, shininess, [x, y, z], angle, [sx, sy, sz]) in instances {
            (gl.glMaterialfv)(GL_FRONT, GL_AMBIENT, ambient.as_ptr());
            (gl.glMaterialfv)(GL_FRONT, GL_DIFFUSE, diffuse.as_ptr());
            (gl.glMaterialfv)(GL_FRONT, GL_EMISSION, emission.as_ptr());
            (gl.glMaterialf)(GL_FRONT, GL_SHININESS, shininess);
            (gl.glPushMatrix)();
            (gl.glTranslatef)(x, y, z);
            (gl.glRotatef)(angle, 0.0, 0.0, 1.0);
            (gl.glScalef)(sx, sy, sz);
            (gl.glCallList)(list);
            (gl.glPopMatrix)();
        }

        (gl.glDeleteLists)(list, 1);

        // An open tube lit on both sides: the outside (front faces) with the front material,
        // the inside (back faces) with the back material and the reversed normal. No culling
        // in this scene: the tube's back faces must be drawn.
        (gl.glLightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 1);
        let outside = [0.95f32, 0.7, 0.25, OBJECT_ALPHAS[5]];
        (gl.glMaterialfv)(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, outside.as_ptr());
        (gl.glMaterialfv)(GL_FRONT, GL_EMISSION, [0.0f32, 0.0, 0.0, 1.0].as_ptr());
        (gl.glMaterialf)(GL_FRONT, GL_SHININESS, 32.0);
        let inside = [0.3f32, 0.5, 0.9, OBJECT_ALPHAS[6]];
        (gl.glMaterialfv)(GL_BACK, GL_AMBIENT_AND_DIFFUSE, inside.as_ptr());
        (gl.glMaterialfv)(GL_BACK, GL_SPECULAR, [0.5f32, 0.5, 0.5, 1.0].as_ptr());
        (gl.glMaterialf)(GL_BACK, GL_SHININESS, 24.0);
        (gl.glPushMatrix)();
        (gl.glTranslatef)(2.0, -0.3, 1.0);
        (gl.glRotatef)(32.0, 1.0, 0.0, 0.0);
        let (radius, half_height, slices) = (0.45f32, 0.45f32, 32);
        (gl.glBegin)(GL_QUAD_STRIP);
        for j in 0..=slices {
            let phi = 2.0 * PI * j as f32 / slices as f32;
            let (x, z) = (phi.cos(), phi.sin());
            (gl.glNormal3f)(x, 0.0, z);
            (gl.glVertex3f)(radius * x, -half_height, radius * z);
            (gl.glVertex3f)(radius * x, half_height, radius * z);
        }
        (gl.glEnd)();
        (gl.glPopMatrix)();
        (gl.glLightModeli)(GL_LIGHT_MODEL_TWO_SIDE, 0);
    }
}
