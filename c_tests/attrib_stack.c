/* ffl-test: differential */
/*
 * Attribute stacks (§6.1.14). For each glPushAttrib bit, then for each glPushClientAttrib
 * bit: one setting of every state, a push of the bit, a second setting of every state, a
 * pop; then every queryable state is printed: the state tables' groups of the bit come back,
 * the rest keeps the second setting. Then the stack depths, GL_STACK_OVERFLOW,
 * GL_STACK_UNDERFLOW and GL_INVALID_OPERATION between glBegin and glEnd.
 * Left out here, where OSMesa departs from the spec (osmesa_diff_attrib_stack.c): color
 * material stays disabled (OSMesa's materials do not track a current color restored by
 * glPopAttrib), and the light enables, GL_COLOR_SUM, GL_FOG_COORD_SRC and
 * GL_GENERATE_MIPMAP_HINT keep one value (OSMesa's glPopAttrib does not restore them). Texture coordinate generation stays off and
 * the texture matrix the identity while the raster position is set (fflight has neither).
 */
#include "ffl_test.h"

typedef struct {
    GLenum pname;
    int count;
    char kind; /* 'i' integers, 'f' floats, 'b' booleans, 'c' capability */
} query;

static const query queries[] = {
    { GL_CURRENT_COLOR, 4, 'f' }, { GL_CURRENT_NORMAL, 3, 'f' },
    { GL_CURRENT_TEXTURE_COORDS, 4, 'f' }, { GL_EDGE_FLAG, 1, 'b' },
    { GL_CURRENT_RASTER_POSITION, 4, 'f' }, { GL_CURRENT_RASTER_POSITION_VALID, 1, 'b' },
    { GL_CURRENT_RASTER_COLOR, 4, 'f' }, { GL_CURRENT_RASTER_TEXTURE_COORDS, 4, 'f' },
    { GL_CURRENT_RASTER_DISTANCE, 1, 'f' },
    { GL_POINT_SIZE, 1, 'f' }, { GL_POINT_SIZE_MIN, 1, 'f' }, { GL_POINT_SIZE_MAX, 1, 'f' },
    { GL_POINT_FADE_THRESHOLD_SIZE, 1, 'f' }, { GL_POINT_DISTANCE_ATTENUATION, 3, 'f' },
    { GL_LINE_WIDTH, 1, 'f' }, { GL_LINE_STIPPLE_PATTERN, 1, 'i' },
    { GL_LINE_STIPPLE_REPEAT, 1, 'i' },
    { GL_CULL_FACE_MODE, 1, 'i' }, { GL_FRONT_FACE, 1, 'i' }, { GL_POLYGON_MODE, 2, 'i' },
    { GL_POLYGON_OFFSET_FACTOR, 1, 'f' }, { GL_POLYGON_OFFSET_UNITS, 1, 'f' },
    { GL_MAP_COLOR, 1, 'b' }, { GL_MAP_STENCIL, 1, 'b' }, { GL_INDEX_SHIFT, 1, 'i' },
    { GL_INDEX_OFFSET, 1, 'i' }, { GL_RED_SCALE, 1, 'f' }, { GL_RED_BIAS, 1, 'f' },
    { GL_GREEN_SCALE, 1, 'f' }, { GL_BLUE_BIAS, 1, 'f' }, { GL_DEPTH_SCALE, 1, 'f' },
    { GL_ZOOM_X, 1, 'f' }, { GL_ZOOM_Y, 1, 'f' }, { GL_READ_BUFFER, 1, 'i' },
    { GL_LIGHT_MODEL_AMBIENT, 4, 'f' }, { GL_LIGHT_MODEL_LOCAL_VIEWER, 1, 'b' },
    { GL_LIGHT_MODEL_TWO_SIDE, 1, 'b' }, { GL_LIGHT_MODEL_COLOR_CONTROL, 1, 'i' },
    { GL_COLOR_MATERIAL_FACE, 1, 'i' }, { GL_COLOR_MATERIAL_PARAMETER, 1, 'i' },
    { GL_SHADE_MODEL, 1, 'i' },
    { GL_FOG_COLOR, 4, 'f' }, { GL_FOG_INDEX, 1, 'f' }, { GL_FOG_DENSITY, 1, 'f' },
    { GL_FOG_START, 1, 'f' }, { GL_FOG_END, 1, 'f' }, { GL_FOG_MODE, 1, 'i' },
    { GL_FOG_COORD_SRC, 1, 'i' },
    { GL_DEPTH_FUNC, 1, 'i' }, { GL_DEPTH_CLEAR_VALUE, 1, 'f' }, { GL_DEPTH_WRITEMASK, 1, 'b' },
    { GL_ACCUM_CLEAR_VALUE, 4, 'f' },
    { GL_STENCIL_FUNC, 1, 'i' }, { GL_STENCIL_VALUE_MASK, 1, 'i' }, { GL_STENCIL_REF, 1, 'i' },
    { GL_STENCIL_FAIL, 1, 'i' }, { GL_STENCIL_PASS_DEPTH_FAIL, 1, 'i' },
    { GL_STENCIL_PASS_DEPTH_PASS, 1, 'i' }, { GL_STENCIL_CLEAR_VALUE, 1, 'i' },
    { GL_STENCIL_WRITEMASK, 1, 'i' },
    { GL_VIEWPORT, 4, 'i' }, { GL_DEPTH_RANGE, 2, 'f' },
    { GL_MATRIX_MODE, 1, 'i' },
    { GL_ALPHA_TEST_FUNC, 1, 'i' }, { GL_ALPHA_TEST_REF, 1, 'f' }, { GL_BLEND_SRC_RGB, 1, 'i' },
    { GL_BLEND_DST_RGB, 1, 'i' }, { GL_BLEND_SRC_ALPHA, 1, 'i' }, { GL_BLEND_DST_ALPHA, 1, 'i' },
    { GL_BLEND_EQUATION, 1, 'i' }, { GL_BLEND_COLOR, 4, 'f' }, { GL_LOGIC_OP_MODE, 1, 'i' },
    { GL_DRAW_BUFFER, 1, 'i' }, { GL_INDEX_WRITEMASK, 1, 'i' }, { GL_COLOR_WRITEMASK, 4, 'b' },
    { GL_COLOR_CLEAR_VALUE, 4, 'f' }, { GL_INDEX_CLEAR_VALUE, 1, 'f' },
    { GL_PERSPECTIVE_CORRECTION_HINT, 1, 'i' }, { GL_POINT_SMOOTH_HINT, 1, 'i' },
    { GL_LINE_SMOOTH_HINT, 1, 'i' }, { GL_POLYGON_SMOOTH_HINT, 1, 'i' }, { GL_FOG_HINT, 1, 'i' },
    { GL_GENERATE_MIPMAP_HINT, 1, 'i' }, { GL_TEXTURE_COMPRESSION_HINT, 1, 'i' },
    { GL_SCISSOR_BOX, 4, 'i' },
    { GL_SAMPLE_COVERAGE_VALUE, 1, 'f' }, { GL_SAMPLE_COVERAGE_INVERT, 1, 'b' },
    { GL_MODELVIEW_MATRIX, 16, 'f' }, { GL_PROJECTION_MATRIX, 16, 'f' },
    { GL_TEXTURE_MATRIX, 16, 'f' },
    /* client state */
    { GL_UNPACK_SWAP_BYTES, 1, 'b' }, { GL_UNPACK_LSB_FIRST, 1, 'b' },
    { GL_UNPACK_ROW_LENGTH, 1, 'i' }, { GL_UNPACK_SKIP_ROWS, 1, 'i' },
    { GL_UNPACK_SKIP_PIXELS, 1, 'i' }, { GL_UNPACK_ALIGNMENT, 1, 'i' },
    { GL_UNPACK_IMAGE_HEIGHT, 1, 'i' }, { GL_UNPACK_SKIP_IMAGES, 1, 'i' },
    { GL_PACK_SWAP_BYTES, 1, 'b' }, { GL_PACK_LSB_FIRST, 1, 'b' },
    { GL_PACK_ROW_LENGTH, 1, 'i' }, { GL_PACK_SKIP_ROWS, 1, 'i' },
    { GL_PACK_SKIP_PIXELS, 1, 'i' }, { GL_PACK_ALIGNMENT, 1, 'i' },
    { GL_PACK_IMAGE_HEIGHT, 1, 'i' }, { GL_PACK_SKIP_IMAGES, 1, 'i' },
    { GL_VERTEX_ARRAY, 1, 'c' }, { GL_NORMAL_ARRAY, 1, 'c' }, { GL_COLOR_ARRAY, 1, 'c' },
    { GL_INDEX_ARRAY, 1, 'c' }, { GL_TEXTURE_COORD_ARRAY, 1, 'c' },
    { GL_EDGE_FLAG_ARRAY, 1, 'c' },
    { GL_VERTEX_ARRAY_SIZE, 1, 'i' }, { GL_VERTEX_ARRAY_TYPE, 1, 'i' },
    { GL_VERTEX_ARRAY_STRIDE, 1, 'i' }, { GL_NORMAL_ARRAY_TYPE, 1, 'i' },
    { GL_NORMAL_ARRAY_STRIDE, 1, 'i' }, { GL_COLOR_ARRAY_SIZE, 1, 'i' },
    { GL_COLOR_ARRAY_TYPE, 1, 'i' }, { GL_COLOR_ARRAY_STRIDE, 1, 'i' },
    { GL_TEXTURE_COORD_ARRAY_SIZE, 1, 'i' }, { GL_TEXTURE_COORD_ARRAY_TYPE, 1, 'i' },
    { GL_TEXTURE_COORD_ARRAY_STRIDE, 1, 'i' }, { GL_EDGE_FLAG_ARRAY_STRIDE, 1, 'i' },
    { GL_ARRAY_BUFFER_BINDING, 1, 'i' }, { GL_ELEMENT_ARRAY_BUFFER_BINDING, 1, 'i' },
    { GL_VERTEX_ARRAY_BUFFER_BINDING, 1, 'i' }, { GL_NORMAL_ARRAY_BUFFER_BINDING, 1, 'i' },
    { GL_COLOR_ARRAY_BUFFER_BINDING, 1, 'i' },
    { GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 1, 'i' },
    { GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1, 'i' },
};

/* Every capability. */
static const GLenum caps[] = {
    GL_LIGHTING, GL_NORMALIZE, GL_RESCALE_NORMAL, GL_CULL_FACE, GL_CLIP_PLANE0,
    GL_CLIP_PLANE1, GL_CLIP_PLANE2, GL_CLIP_PLANE3, GL_CLIP_PLANE4, GL_CLIP_PLANE5,
    GL_AUTO_NORMAL, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q, GL_SCISSOR_TEST,
    GL_ALPHA_TEST, GL_STENCIL_TEST, GL_DEPTH_TEST, GL_BLEND, GL_DITHER, GL_INDEX_LOGIC_OP,
    GL_COLOR_LOGIC_OP, GL_FOG, GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_LINE_STIPPLE,
    GL_POLYGON_SMOOTH, GL_POLYGON_STIPPLE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_FILL, GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_COLOR_MATERIAL, GL_COLOR_SUM, GL_LIGHT0,
    GL_LIGHT1, GL_LIGHT2, GL_LIGHT3, GL_LIGHT4, GL_LIGHT5, GL_LIGHT6, GL_LIGHT7
};
/* The capabilities set_everything toggles: all but the last ten, which keep one value. */
#define CAP_COUNT ((int)(sizeof caps / sizeof caps[0]) - 10)

static const GLenum light_pnames[] = {
    GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
    GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION
};
static const int light_counts[] = { 4, 4, 4, 4, 3, 1, 1, 1, 1, 1 };
static const GLenum material_pnames[] = {
    GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS, GL_COLOR_INDEXES
};
static const int material_counts[] = { 4, 4, 4, 4, 1, 3 };
static const GLenum hints[] = {
    GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT, GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT, GL_TEXTURE_COMPRESSION_HINT
};
static const GLenum client_arrays[] = {
    GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY
};
static const GLenum pack_pnames[] = {
    GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS,
    GL_PACK_SKIP_PIXELS, GL_PACK_ALIGNMENT, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES
};
static const GLenum unpack_pnames[] = {
    GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,
    GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES
};
/* The initial value of each pack_pnames and unpack_pnames entry. */
static const GLint pack_initial[] = { 0, 0, 0, 0, 0, 4, 0, 0 };

static GLuint buffers[4];
static GLubyte client_memory[1024];

/* Sets every state the queries show; k is 1 or 2 and every value depends on it. */
static void set_everything(int k)
{
    const float f = (float)k;
    const int odd = k % 2;
    GLfloat c[4];
    GLubyte stipple[128];
    int i, light;

    c[0] = 0.1f * f; c[1] = 0.2f * f; c[2] = 0.3f * f; c[3] = 0.4f * f;
    glColor4f(c[0], c[1], c[2], c[3]);
    glNormal3f(0.1f * f, 0.5f, 0.7f);
    glTexCoord4f(1.0f + c[0], 1.0f + c[1], 1.0f + c[2], 1.0f + c[3]);
    glEdgeFlag(odd ? GL_FALSE : GL_TRUE);
    glPointSize(f);
    glPointParameterf(GL_POINT_SIZE_MIN, f);
    glPointParameterf(GL_POINT_SIZE_MAX, 10.0f * f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.0f * f);
    c[0] = f; c[1] = 2.0f; c[2] = 3.0f;
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, c);
    glLineWidth(f + 0.5f);
    glLineStipple(k + 2, (GLushort)(0x0F0F * k));
    glCullFace(odd ? GL_FRONT : GL_FRONT_AND_BACK);
    glFrontFace(odd ? GL_CW : GL_CCW);
    glPolygonMode(GL_FRONT, odd ? GL_LINE : GL_POINT);
    glPolygonMode(GL_BACK, odd ? GL_POINT : GL_LINE);
    glPolygonOffset(f, -f);
    for (i = 0; i < 128; i++)
        stipple[i] = (GLubyte)(i * k);
    for (i = 0; i < 8; i++)
        glPixelStorei(unpack_pnames[i], pack_initial[i]);
    glPolygonStipple(stipple);
    glPixelTransferi(GL_MAP_COLOR, k - 1);
    glPixelTransferi(GL_MAP_STENCIL, k - 1);
    glPixelTransferi(GL_INDEX_SHIFT, k + 1);
    glPixelTransferi(GL_INDEX_OFFSET, k + 2);
    glPixelTransferf(GL_RED_SCALE, f + 0.5f);
    glPixelTransferf(GL_RED_BIAS, f + 0.25f);
    glPixelTransferf(GL_GREEN_SCALE, f + 0.75f);
    glPixelTransferf(GL_BLUE_BIAS, f - 0.5f);
    glPixelTransferf(GL_DEPTH_SCALE, 2.0f * f);
    glPixelZoom(f, 2.0f * f);
    glReadBuffer(odd ? GL_LEFT : GL_FRONT_LEFT);
    for (light = 0; light < 8; light++) {
        GLenum l = GL_LIGHT0 + (GLenum)light;
        float s = f + (float)light, d = 0.01f * (float)(light + 1);
        GLfloat v[4];
        v[0] = d * f; v[1] = 2.0f * d * f; v[2] = 3.0f * d * f; v[3] = 1.0f;
        glLightfv(l, GL_AMBIENT, v);
        v[0] *= 2.0f;
        glLightfv(l, GL_DIFFUSE, v);
        v[1] *= 2.0f;
        glLightfv(l, GL_SPECULAR, v);
        v[0] = s; v[1] = 1.0f; v[2] = 2.0f; v[3] = 1.0f;
        glLightfv(l, GL_POSITION, v);
        v[0] = 0.0f; v[1] = s; v[2] = -1.0f;
        glLightfv(l, GL_SPOT_DIRECTION, v);
        glLightf(l, GL_SPOT_EXPONENT, s);
        glLightf(l, GL_SPOT_CUTOFF, 40.0f + s);
        glLightf(l, GL_CONSTANT_ATTENUATION, s);
        glLightf(l, GL_LINEAR_ATTENUATION, s * 0.1f);
        glLightf(l, GL_QUADRATIC_ATTENUATION, s * 0.01f);
    }
    for (i = 0; i < 2; i++) {
        GLenum face = i ? GL_BACK : GL_FRONT;
        float base = 0.1f * (float)(i + 1);
        GLfloat v[4];
        v[0] = base * f; v[1] = 0.1f * f; v[2] = 0.2f * f; v[3] = 0.5f;
        glMaterialfv(face, GL_AMBIENT, v);
        v[1] += 0.1f;
        glMaterialfv(face, GL_DIFFUSE, v);
        v[2] += 0.1f;
        glMaterialfv(face, GL_SPECULAR, v);
        v[0] = 0.05f * f;
        glMaterialfv(face, GL_EMISSION, v);
        glMaterialf(face, GL_SHININESS, f + base);
        v[0] = f; v[1] = 2.0f * f; v[2] = 3.0f * f;
        glMaterialfv(face, GL_COLOR_INDEXES, v);
    }
    c[0] = 0.02f * f; c[1] = 0.04f * f; c[2] = 0.06f * f; c[3] = 1.0f;
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, c);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, k - 1);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, k - 1);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, odd ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    glColorMaterial(odd ? GL_BACK : GL_FRONT, odd ? GL_EMISSION : GL_SPECULAR);
    glShadeModel(odd ? GL_FLAT : GL_SMOOTH);
    c[0] = 0.1f * f; c[1] = 0.2f * f; c[2] = 0.3f * f; c[3] = 0.4f * f;
    glFogfv(GL_FOG_COLOR, c);
    glFogf(GL_FOG_INDEX, f);
    glFogf(GL_FOG_DENSITY, f);
    glFogf(GL_FOG_START, f);
    glFogf(GL_FOG_END, 10.0f * f);
    glFogi(GL_FOG_MODE, odd ? GL_LINEAR : GL_EXP2);
    glDepthFunc(odd ? GL_GREATER : GL_EQUAL);
    glClearDepth(0.25 * f);
    glDepthMask(odd ? GL_FALSE : GL_TRUE);
    glClearAccum(-0.1f * f, 0.2f * f, -0.3f * f, 0.4f * f);
    glStencilFunc(odd ? GL_NEVER : GL_LEQUAL, k, 0xF0u + (GLuint)k);
    glStencilOp(odd ? GL_ZERO : GL_INVERT, odd ? GL_INCR : GL_DECR,
                odd ? GL_REPLACE : GL_INCR_WRAP);
    glClearStencil(k);
    glStencilMask((GLuint)k);
    glViewport(k, 2 * k, 30 * k, 40 * k);
    glDepthRange(0.1 * f, 0.3 * f);
    glAlphaFunc(odd ? GL_LESS : GL_GEQUAL, 0.25f * f);
    glBlendFuncSeparate(odd ? GL_SRC_COLOR : GL_DST_COLOR, odd ? GL_SRC_ALPHA : GL_DST_ALPHA,
                        odd ? GL_CONSTANT_COLOR : GL_CONSTANT_ALPHA,
                        odd ? GL_ONE_MINUS_SRC_COLOR : GL_ONE_MINUS_DST_COLOR);
    glBlendEquation(odd ? GL_FUNC_SUBTRACT : GL_MAX);
    glBlendColor(0.1f * f, 0.2f * f, 0.3f * f, 0.4f * f);
    glLogicOp(odd ? GL_AND : GL_XOR);
    glDrawBuffer(odd ? GL_NONE : GL_FRONT_AND_BACK);
    glIndexMask((GLuint)k);
    glColorMask((GLboolean)odd, (GLboolean)!odd, (GLboolean)odd, (GLboolean)!odd);
    glClearColor(0.2f * f, 0.1f * f, 0.3f * f, 0.4f * f);
    glClearIndex(f);
    for (i = 0; i < 7; i++) {
        if (hints[i] != GL_GENERATE_MIPMAP_HINT)
            glHint(hints[i], (i + k) % 2 ? GL_NICEST : GL_FASTEST);
    }
    glScissor(k, 3, 4 * k, 5);
    glSampleCoverage(0.25f * f, (GLboolean)odd);
    for (i = 0; i < 6; i++) {
        GLdouble plane[4];
        plane[0] = f; plane[1] = i; plane[2] = 1.0; plane[3] = 10.0;
        glClipPlane(GL_CLIP_PLANE0 + (GLenum)i, plane);
    }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glScaled(1.0 + 0.1 * f, 1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotated(10.0 * f, 0.0, 0.0, 1.0);
    /* The raster position, unlit: invalid in the first setting, valid in the second. */
    glDisable(GL_LIGHTING);
    for (i = 0; i < 4; i++)
        glDisable(GL_TEXTURE_GEN_S + (GLenum)i);
    glRasterPos3f(odd ? 100.0f : 0.2f, 0.2f, -0.5f);
    glMatrixMode(odd ? GL_TEXTURE : GL_PROJECTION);
    for (i = 0; i < CAP_COUNT; i++) {
        if ((i + k) % 2 == 0)
            glEnable(caps[i]);
        else
            glDisable(caps[i]);
    }
    glPixelStorei(GL_UNPACK_SWAP_BYTES, k - 1);
    glPixelStorei(GL_UNPACK_LSB_FIRST, k - 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, k + 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, k + 2);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, k + 3);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1 << k);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, k + 4);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, k + 5);
    for (i = 0; i < 8; i++)
        glPixelStorei(pack_pnames[i], i == 5 ? 1 << k : i < 2 ? k - 1 : k + i);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[2 * odd + 1]);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[2 * odd]);
    glVertexPointer(2 + odd, odd ? GL_SHORT : GL_INT, 4 * k, (const GLvoid *)(size_t)(16 * k));
    glNormalPointer(odd ? GL_BYTE : GL_SHORT, 4 * k, (const GLvoid *)(size_t)(16 * k));
    glBindBuffer(GL_ARRAY_BUFFER, odd ? buffers[2] : 0);
    glColorPointer(3 + odd, odd ? GL_UNSIGNED_BYTE : GL_DOUBLE, 4 * k, client_memory + 16 * k);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[k % 2]);
    glTexCoordPointer(1 + odd, odd ? GL_SHORT : GL_DOUBLE, 4 * k, (const GLvoid *)(size_t)(8 * k));
    glEdgeFlagPointer(4 * k, (const GLvoid *)(size_t)(8 * k));
    for (i = 0; i < 6; i++) {
        if ((i + k) % 2 == 0)
            glEnableClientState(client_arrays[i]);
        else
            glDisableClientState(client_arrays[i]);
    }
}

static void print_everything(const char *what)
{
    GLint pack[8];
    GLubyte stipple[128];
    GLfloat v[4];
    size_t q;
    int i, j;

    printf("%s\n", what);
    for (q = 0; q < sizeof queries / sizeof queries[0]; q++) {
        char label[32];
        sprintf(label, " q%04x", (unsigned)queries[q].pname);
        switch (queries[q].kind) {
        case 'i': ffl_print_ints(label, queries[q].pname, queries[q].count); break;
        case 'f': ffl_print_floats(label, queries[q].pname, queries[q].count); break;
        case 'b': ffl_print_bools(label, queries[q].pname, queries[q].count, 0); break;
        default: ffl_print_bools(label, queries[q].pname, 1, 1); break;
        }
    }
    for (i = 0; i < CAP_COUNT + 10; i++)
        printf(" cap%04x %d\n", (unsigned)caps[i], (int)glIsEnabled(caps[i]));
    for (i = 0; i < 8; i++) {
        for (j = 0; j < 10; j++) {
            glGetLightfv(GL_LIGHT0 + (GLenum)i, light_pnames[j], v);
            printf(" light%d_%04x", i, (unsigned)light_pnames[j]);
            ffl_pfv("f", v, light_counts[j]);
            printf("\n");
        }
    }
    for (i = 0; i < 2; i++) {
        for (j = 0; j < 6; j++) {
            glGetMaterialfv(i ? GL_BACK : GL_FRONT, material_pnames[j], v);
            printf(" material%d_%04x", i, (unsigned)material_pnames[j]);
            ffl_pfv("f", v, material_counts[j]);
            printf("\n");
        }
    }
    for (i = 0; i < 6; i++) {
        GLdouble plane[4];
        glGetClipPlane(GL_CLIP_PLANE0 + (GLenum)i, plane);
        printf(" clip_plane%d", i);
        ffl_pdv("f", plane, 4);
        printf("\n");
    }
    /* The stipple with the initial pack modes, the context's put back after. */
    for (i = 0; i < 8; i++) {
        glGetIntegerv(pack_pnames[i], &pack[i]);
        glPixelStorei(pack_pnames[i], pack_initial[i]);
    }
    memset(stipple, 0, sizeof stipple);
    glGetPolygonStipple(stipple);
    for (i = 0; i < 8; i++)
        glPixelStorei(pack_pnames[i], pack[i]);
    printf(" stipple");
    for (i = 0; i < 128; i++)
        printf(" %d", stipple[i]);
    printf("\n");
    ffl_print_error(" error");
}

int main(void)
{
    static const GLbitfield server_bits[] = {
        GL_CURRENT_BIT, GL_POINT_BIT, GL_LINE_BIT, GL_POLYGON_BIT, GL_POLYGON_STIPPLE_BIT,
        GL_PIXEL_MODE_BIT, GL_LIGHTING_BIT, GL_FOG_BIT, GL_DEPTH_BUFFER_BIT,
        GL_ACCUM_BUFFER_BIT, GL_STENCIL_BUFFER_BIT, GL_VIEWPORT_BIT, GL_TRANSFORM_BIT,
        GL_ENABLE_BIT, GL_COLOR_BUFFER_BIT, GL_HINT_BIT, GL_EVAL_BIT, GL_LIST_BIT,
        GL_TEXTURE_BIT, GL_SCISSOR_BIT, GL_MULTISAMPLE_BIT, GL_ALL_ATTRIB_BITS,
        GL_LIGHTING_BIT | GL_FOG_BIT | GL_VIEWPORT_BIT, 0
    };
    static const GLbitfield client_bits[] = {
        GL_CLIENT_PIXEL_STORE_BIT, GL_CLIENT_VERTEX_ARRAY_BIT, GL_CLIENT_ALL_ATTRIB_BITS, 0
    };
    size_t b;
    int i;

    ffl_test_init();
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT5);
    glGenBuffers(4, buffers);
    for (i = 0; i < 4; i++) {
        glBindBuffer(GL_ARRAY_BUFFER, buffers[i]);
        glBufferData(GL_ARRAY_BUFFER, 64, client_memory, GL_STATIC_DRAW);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    ffl_print_ints("max_depth", GL_MAX_ATTRIB_STACK_DEPTH, 1);
    ffl_print_ints("max_client_depth", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 1);

    for (b = 0; b < sizeof server_bits / sizeof server_bits[0]; b++) {
        char what[64];
        set_everything(1);
        glPushAttrib(server_bits[b]);
        ffl_print_ints("depth_after_push", GL_ATTRIB_STACK_DEPTH, 1);
        set_everything(2);
        glPopAttrib();
        sprintf(what, "popped_server_bits 0x%08lx", (unsigned long)server_bits[b]);
        print_everything(what);
    }
    for (b = 0; b < sizeof client_bits / sizeof client_bits[0]; b++) {
        char what[64];
        set_everything(1);
        glPushClientAttrib(client_bits[b]);
        ffl_print_ints("client_depth_after_push", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
        set_everything(2);
        glPopClientAttrib();
        sprintf(what, "popped_client_bits 0x%08lx", (unsigned long)client_bits[b]);
        print_everything(what);
    }

    /* Depths, overflow, underflow: a failed call changes nothing. */
    for (i = 0; i < 16; i++) {
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    }
    ffl_print_ints("full_depth", GL_ATTRIB_STACK_DEPTH, 1);
    ffl_print_ints("full_client_depth", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    ffl_print_error("pushes");
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    ffl_print_error("push_overflow");
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    ffl_print_error("client_push_overflow");
    ffl_print_ints("depth_after_overflow", GL_ATTRIB_STACK_DEPTH, 1);
    ffl_print_ints("client_depth_after_overflow", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    for (i = 0; i < 16; i++) {
        glPopAttrib();
        glPopClientAttrib();
    }
    ffl_print_error("pops");
    glPopAttrib();
    ffl_print_error("pop_underflow");
    glPopClientAttrib();
    ffl_print_error("client_pop_underflow");
    ffl_print_ints("depth_after_underflow", GL_ATTRIB_STACK_DEPTH, 1);

    /* Between glBegin and glEnd. */
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    glBegin(GL_POINTS);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glEnd();
    ffl_print_error("push_in_begin_end");
    glBegin(GL_POINTS);
    glPopAttrib();
    glEnd();
    ffl_print_error("pop_in_begin_end");
    glBegin(GL_POINTS);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    glEnd();
    ffl_print_error("client_push_in_begin_end");
    glBegin(GL_POINTS);
    glPopClientAttrib();
    glEnd();
    ffl_print_error("client_pop_in_begin_end");
    ffl_print_ints("depth_after_begin_end", GL_ATTRIB_STACK_DEPTH, 1);
    ffl_print_ints("client_depth_after_begin_end", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
    return 0;
}
