//! The seed corpus of the C ABI fuzz target (`fuzz/seeds/capi_calls/`), written as call
//! sequences in the encoding `harness.rs` decodes: lighting and feedback, selection with tiny
//! buffers and deep name stacks, matrix and attribute stack overflows, glBegin/glEnd nesting
//! errors, vertex arrays, buffer objects, display lists, evaluators, textures, capture, and
//! contexts created, made current and destroyed. `tests/fuzz_replay.rs` checks that the files
//! are these (`FFLIGHT_BLESS=1` rewrites them) and replays them.

use fflight::gl::*;

use crate::harness::FUNCTIONS;

/// An input being written.
#[derive(Default)]
pub struct Seed(Vec<u8>);

impl Seed {
    /// Calls `name`; its arguments follow.
    fn call(mut self, name: &str) -> Seed {
        let index = FUNCTIONS
            .iter()
            .position(|&f| f == name)
            .unwrap_or_else(|| panic!("{name} is not in the call table"));
        self.0.extend_from_slice(&(index as u16).to_le_bytes());
        self
    }

    /// Repeats the call `name` (its arguments follow) `times` times (2 to 80).
    fn repeat(mut self, times: u8, name: &str) -> Seed {
        let op = FUNCTIONS.len() as u16;
        self.0.extend_from_slice(&op.to_le_bytes());
        self.0.push(times - 2);
        let index = FUNCTIONS.iter().position(|&f| f == name).unwrap();
        self.0.extend_from_slice(&(index as u16).to_le_bytes());
        self
    }

    /// glBegin(mode), `vertices` vertices with normals from the float region, glEnd.
    fn primitive(mut self, mode: GLenum, vertices: u8) -> Seed {
        let op = FUNCTIONS.len() as u16 + 2;
        self.0.extend_from_slice(&op.to_le_bytes());
        self.0.push(mode as u8);
        self.0.push(vertices);
        for k in 0..vertices {
            self.0.push(1);
            self.0.push(k.wrapping_mul(37));
        }
        self
    }

    /// A GLenum argument, exactly.
    fn e(mut self, value: GLenum) -> Seed {
        self.0.push(0);
        self.0.extend_from_slice(&value.to_le_bytes());
        self
    }

    /// An integer argument, exactly (sizes are folded into their range by the decoder).
    fn i(mut self, value: i32) -> Seed {
        self.0.push(7);
        self.0.extend_from_slice(&value.to_le_bytes());
        self
    }

    fn f(mut self, value: f32) -> Seed {
        self.0.push(3);
        self.0.extend_from_slice(&value.to_bits().to_le_bytes());
        self
    }

    #[allow(dead_code)]
    fn d(mut self, value: f64) -> Seed {
        self.0.push(0);
        let bits = value.to_bits();
        self.0.extend_from_slice(&(bits as u32).to_le_bytes());
        self.0
            .extend_from_slice(&((bits >> 32) as u32).to_le_bytes());
        self
    }

    /// A pointer into the argument's region at `offset` * 8 bytes.
    fn p(mut self, offset: u8) -> Seed {
        self.0.push(1);
        self.0.push(offset);
        self
    }

    /// An output pointer.
    fn o(mut self) -> Seed {
        self.0.push(1);
        self
    }

    /// A raw byte (GLboolean, a harness choice).
    fn b(mut self, value: u8) -> Seed {
        self.0.push(value);
        self
    }

    fn mask(mut self, value: GLbitfield) -> Seed {
        self.0.push(0);
        self.0.extend_from_slice(&value.to_le_bytes());
        self
    }

    fn bytes(self) -> Vec<u8> {
        self.0
    }
}

fn lit_scene(seed: Seed) -> Seed {
    seed.call("glViewport")
        .i(0)
        .i(0)
        .i(64)
        .i(64)
        .call("glEnable")
        .e(GL_LIGHTING)
        .call("glEnable")
        .e(GL_LIGHT0)
        .call("glLightfv")
        .e(GL_LIGHT0)
        .e(GL_POSITION)
        .p(3)
        .call("glLightfv")
        .e(GL_LIGHT0)
        .e(GL_SPOT_CUTOFF)
        .p(9)
        .call("glMaterialfv")
        .e(GL_FRONT_AND_BACK)
        .e(GL_SHININESS)
        .p(15)
        .call("glLightModeli")
        .e(GL_LIGHT_MODEL_TWO_SIDE)
        .i(1)
}

fn feedback(seed: Seed, size: i32, kind: GLenum) -> Seed {
    seed.call("glFeedbackBuffer")
        .i(size)
        .e(kind)
        .b(1)
        .call("glRenderMode")
        .e(GL_FEEDBACK)
}

/// The seeds, named.
pub fn seeds() -> Vec<(&'static str, Vec<u8>)> {
    let mut out = Vec::new();
    let lit_feedback = feedback(lit_scene(Seed::default()), 4096, GL_3D_COLOR_TEXTURE)
        .primitive(GL_TRIANGLES, 6)
        .primitive(GL_QUAD_STRIP, 8)
        .primitive(GL_POLYGON, 7)
        .primitive(GL_LINE_LOOP, 5)
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("lit_feedback", lit_feedback.bytes()));

    let tiny_feedback = feedback(lit_scene(Seed::default()), 9, GL_4D_COLOR_TEXTURE)
        .primitive(GL_POLYGON, 8)
        .call("glPassThrough")
        .f(7.0)
        .call("glRasterPos3f")
        .f(0.5)
        .f(0.5)
        .f(0.0)
        .call("glBitmap")
        .i(8)
        .i(8)
        .f(0.0)
        .f(0.0)
        .f(1.0)
        .f(1.0)
        .p(0)
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("tiny_feedback", tiny_feedback.bytes()));

    let selection = Seed::default()
        .call("glSelectBuffer")
        .i(7)
        .b(1)
        .call("glRenderMode")
        .e(GL_SELECT)
        .call("glInitNames")
        .repeat(70, "glPushName")
        .i(3)
        .primitive(GL_TRIANGLES, 3)
        .call("glLoadName")
        .i(9)
        .repeat(70, "glPopName")
        .primitive(GL_POINTS, 4)
        .call("glRenderMode")
        .e(GL_RENDER)
        .call("glLoadName")
        .i(1);
    out.push(("selection_tiny_buffer", selection.bytes()));

    let stacks = Seed::default()
        .repeat(40, "glPushMatrix")
        .call("glMatrixMode")
        .e(GL_PROJECTION)
        .repeat(40, "glPushMatrix")
        .call("glMatrixMode")
        .e(GL_TEXTURE)
        .repeat(12, "glPushMatrix")
        .call("glMatrixMode")
        .e(GL_COLOR)
        .repeat(6, "glPushMatrix")
        .repeat(20, "glPushAttrib")
        .mask(GL_ALL_ATTRIB_BITS)
        .repeat(20, "glPushClientAttrib")
        .mask(0xffff_ffff)
        .repeat(24, "glPopAttrib")
        .repeat(24, "glPopClientAttrib")
        .repeat(45, "glPopMatrix")
        .call("glMatrixMode")
        .e(GL_MODELVIEW)
        .repeat(45, "glPopMatrix");
    out.push(("stack_overflows", stacks.bytes()));

    let nesting = Seed::default()
        .call("glBegin")
        .e(GL_TRIANGLES)
        .call("glBegin")
        .e(GL_LINES)
        .call("glPushMatrix")
        .call("glVertex3f")
        .f(1.0)
        .f(2.0)
        .f(3.0)
        .call("glGetError")
        .call("glFeedbackBuffer")
        .i(16)
        .e(GL_2D)
        .b(1)
        .call("glRenderMode")
        .e(GL_SELECT)
        .call("glEnd")
        .call("glEnd")
        .call("glEndList")
        .call("glPopMatrix");
    out.push(("begin_end_nesting", nesting.bytes()));

    let arrays = feedback(lit_scene(Seed::default()), 4096, GL_3D_COLOR)
        .call("glVertexPointer")
        .i(3)
        .e(GL_FLOAT)
        .i(0)
        .p(2)
        .call("glNormalPointer")
        .e(GL_SHORT)
        .i(8)
        .p(4)
        .call("glColorPointer")
        .i(4)
        .e(GL_UNSIGNED_BYTE)
        .i(0)
        .p(6)
        .call("glEnableClientState")
        .e(GL_VERTEX_ARRAY)
        .call("glEnableClientState")
        .e(GL_NORMAL_ARRAY)
        .call("glEnableClientState")
        .e(GL_COLOR_ARRAY)
        .call("glDrawArrays")
        .e(GL_TRIANGLE_STRIP)
        .i(0)
        .i(30)
        .call("glDrawElements")
        .e(GL_TRIANGLES)
        .i(24)
        .e(GL_UNSIGNED_INT)
        .p(0)
        .call("glDrawRangeElements")
        .e(GL_LINES)
        .i(0)
        .i(63)
        .i(10)
        .e(GL_UNSIGNED_SHORT)
        .p(3)
        .call("glMultiDrawArrays")
        .e(GL_POINTS)
        .p(1)
        .p(2)
        .i(3)
        .call("glArrayElement")
        .i(5)
        .call("glInterleavedArrays")
        .e(GL_T4F_C4F_N3F_V4F)
        .i(0)
        .p(1)
        .call("glDrawArrays")
        .e(GL_QUADS)
        .i(2)
        .i(16)
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("vertex_arrays", arrays.bytes()));

    let buffers = Seed::default()
        .call("glGenBuffers")
        .i(2)
        .o()
        .call("glBindBuffer")
        .e(GL_ARRAY_BUFFER)
        .i(1)
        .call("glBufferData")
        .e(GL_ARRAY_BUFFER)
        .i(1024)
        .p(0)
        .e(GL_STATIC_DRAW)
        .call("glVertexPointer")
        .i(2)
        .e(GL_FLOAT)
        .i(0)
        .b(0)
        .call("glEnableClientState")
        .e(GL_VERTEX_ARRAY)
        .call("glBindBuffer")
        .e(GL_ELEMENT_ARRAY_BUFFER)
        .i(1)
        .call("glDrawElements")
        .e(GL_TRIANGLES)
        .i(12)
        .e(GL_UNSIGNED_INT)
        .b(0)
        .call("glMapBuffer")
        .e(GL_ARRAY_BUFFER)
        .e(GL_READ_WRITE)
        .call("glDrawArrays")
        .e(GL_POINTS)
        .i(0)
        .i(8)
        .call("glUnmapBuffer")
        .e(GL_ARRAY_BUFFER)
        .call("glDeleteBuffers")
        .i(2)
        .p(0);
    out.push(("buffer_objects", buffers.bytes()));

    let lists = feedback(Seed::default(), 2000, GL_3D_COLOR)
        .call("glGenLists")
        .i(3)
        .call("glNewList")
        .i(1)
        .e(GL_COMPILE_AND_EXECUTE)
        .primitive(GL_TRIANGLE_FAN, 6)
        .call("glCallList")
        .i(1)
        .call("glEndList")
        .call("glNewList")
        .i(2)
        .e(GL_COMPILE)
        .call("glCallList")
        .i(2)
        .call("glCallList")
        .i(1)
        .repeat(70, "glPushMatrix")
        .call("glEndList")
        .call("glCallList")
        .i(2)
        .call("glListBase")
        .i(1)
        .call("glCallLists")
        .i(8)
        .e(GL_UNSIGNED_BYTE)
        .p(0)
        .call("glDeleteLists")
        .i(1)
        .i(3)
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("display_lists", lists.bytes()));

    let evaluators = feedback(lit_scene(Seed::default()), 3000, GL_3D_COLOR_TEXTURE)
        .call("glMap1f")
        .e(GL_MAP1_VERTEX_3)
        .f(0.0)
        .f(1.0)
        .i(3)
        .i(4)
        .p(0)
        .call("glEnable")
        .e(GL_MAP1_VERTEX_3)
        .call("glMapGrid1f")
        .i(8)
        .f(0.0)
        .f(1.0)
        .call("glEvalMesh1")
        .e(GL_LINE)
        .i(0)
        .i(8)
        .call("glMap2f")
        .e(GL_MAP2_VERTEX_4)
        .f(0.0)
        .f(1.0)
        .i(4)
        .i(3)
        .f(0.0)
        .f(1.0)
        .i(12)
        .i(3)
        .p(5)
        .call("glEnable")
        .e(GL_MAP2_VERTEX_4)
        .call("glEnable")
        .e(GL_AUTO_NORMAL)
        .call("glMapGrid2f")
        .i(4)
        .f(0.0)
        .f(1.0)
        .i(4)
        .f(0.0)
        .f(1.0)
        .call("glEvalMesh2")
        .e(GL_FILL)
        .i(0)
        .i(4)
        .i(0)
        .i(4)
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("evaluators", evaluators.bytes()));

    let textures = feedback(Seed::default(), 1000, GL_4D_COLOR_TEXTURE)
        .call("glBindTexture")
        .e(GL_TEXTURE_2D)
        .i(3)
        .call("glTexImage2D")
        .e(GL_TEXTURE_2D)
        .i(0)
        .i(GL_RGBA as i32)
        .i(8)
        .i(8)
        .i(0)
        .e(GL_RGBA)
        .e(GL_FLOAT)
        .p(0)
        .call("glGetTexImage")
        .e(GL_TEXTURE_2D)
        .i(0)
        .e(GL_RGBA)
        .e(GL_UNSIGNED_BYTE)
        .o()
        .call("glTexGeni")
        .e(GL_S)
        .e(GL_TEXTURE_GEN_MODE)
        .i(GL_SPHERE_MAP as i32)
        .call("glEnable")
        .e(GL_TEXTURE_GEN_S)
        .call("glMatrixMode")
        .e(GL_TEXTURE)
        .call("glRotatef")
        .f(30.0)
        .f(0.0)
        .f(0.0)
        .f(1.0)
        .primitive(GL_QUADS, 8)
        .call("glReadPixels")
        .i(0)
        .i(0)
        .i(4)
        .i(4)
        .e(GL_RGBA)
        .e(GL_FLOAT)
        .o()
        .call("glRenderMode")
        .e(GL_RENDER);
    out.push(("textures", textures.bytes()));

    let capture = lit_scene(Seed::default())
        .call("fflCaptureBegin")
        .call("glMultiTexCoord2f")
        .e(GL_TEXTURE3)
        .f(0.5)
        .f(0.25)
        .primitive(GL_TRIANGLE_STRIP, 6)
        .call("fflCaptureEnd")
        .call("fflCaptureReadTexCoords")
        .e(GL_TEXTURE3)
        .i(0)
        .i(64)
        .o()
        .call("fflCaptureReadVertices")
        .i(0)
        .i(64)
        .o()
        .call("fflCaptureReadPrimitives")
        .i(0)
        .i(64)
        .o()
        .call("fflLightVertices")
        .i(100)
        .i(3)
        .p(0)
        .i(0)
        .p(9)
        .i(0)
        .p(20)
        .i(16)
        .o()
        .i(0)
        .o()
        .i(0)
        .o()
        .i(0)
        .o()
        .i(0)
        .o()
        .i(0)
        .o()
        .i(0);
    out.push(("capture_and_bulk", capture.bytes()));

    let contexts = feedback(Seed::default(), 64, GL_3D_COLOR)
        .call("fflCreateContext")
        .call("fflCreateContext")
        .call("fflMakeCurrent")
        .b(1)
        .call("glSelectBuffer")
        .i(4)
        .b(1)
        .call("glRenderMode")
        .e(GL_SELECT)
        .primitive(GL_POINTS, 3)
        .call("fflMakeCurrent")
        .b(0)
        .primitive(GL_LINES, 4)
        .call("fflDestroyContext")
        .b(1)
        .b(0)
        .call("fflGetCurrentContext")
        .call("fflMakeCurrent")
        .b(1)
        .call("glRenderMode")
        .e(GL_RENDER)
        .call("fflDestroyContext")
        .b(1)
        .b(0)
        .call("fflSetThreads")
        .b(3)
        .call("glDrawArrays")
        .e(GL_POINTS)
        .i(0)
        .i(3000);
    out.push(("contexts", contexts.bytes()));

    // Unstructured inputs: whatever the decoder makes of random bytes.
    let mut state = 0x5eed_u64;
    for k in 0..6 {
        let len = 64 << k;
        let bytes = (0..len)
            .map(|_| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (state >> 56) as u8
            })
            .collect();
        out.push((
            [
                "random_64",
                "random_128",
                "random_256",
                "random_512",
                "random_1024",
                "random_2048",
            ][k],
            bytes,
        ));
    }
    out
}

/// Inputs of the findings (`fuzz/regressions/capi_calls/`), replayed by `cargo test`.
pub fn regressions() -> Vec<(&'static str, Vec<u8>)> {
    // A list calling itself twice, nested 64 deep, runs 2^64 times (GL allows it): the
    // harness gives each list being compiled one call (it hung the first campaign).
    let twice = Seed::default()
        .call("glNewList")
        .i(1)
        .e(GL_COMPILE)
        .call("glCallList")
        .i(1)
        .call("glCallList")
        .i(1)
        .repeat(80, "glCallList")
        .i(1)
        .call("glEndList")
        .call("glCallList")
        .i(1);
    // 64 lists, each calling the next, the last drawing in feedback: the deepest nesting
    // with a draw at the bottom (in a debug build about 2 MiB of stack: 16 KiB a level and
    // 1 MiB for the lighting kernel's frame; the replay runs on an 8 MiB thread).
    let mut chain = feedback(lit_scene(Seed::default()), 4096, GL_3D_COLOR);
    for list in 1..=63 {
        chain = chain
            .call("glNewList")
            .i(list)
            .e(GL_COMPILE)
            .call("glCallList")
            .i(list + 1)
            .call("glEndList");
    }
    chain = chain
        .call("glNewList")
        .i(64)
        .e(GL_COMPILE)
        .primitive(GL_TRIANGLES, 6)
        .call("glEndList")
        .call("glCallList")
        .i(1)
        .call("glRenderMode")
        .e(GL_RENDER);
    vec![
        ("list_calling_itself_twice", twice.bytes()),
        ("list_chain_64_deep", chain.bytes()),
    ]
}
