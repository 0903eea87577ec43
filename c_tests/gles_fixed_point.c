/* ffl-test: fflight-only */
/*
 * OpenGL ES 1.1's fixed-point commands (16.16 GLfixed) against their float forms: each x
 * command sets state from fixed values (positive, negative, fractional, the largest and
 * smallest GLfixed, enumerated parameters passed as they are), and the state read back
 * with the float queries must equal what the float command gives with value / 65536
 * (`ref`); the x queries return the state as fixed, rounded to nearest. Then a lit vertex
 * fed back after the whole state is set with x commands equals the one set with float
 * commands. OSMesa has no fixed-point commands: fflight only.
 */
#include "ffl_test.h"

#define FX(v) ((GLfixed)((v) * 65536.0))

static double fx(GLfixed x)
{
    return (double)x / 65536.0;
}

static int failures;

/* The error flag must be `expected` (checked here: error names are not numbers). */
static void check_error(const char *what, GLenum expected)
{
    GLenum e = glGetError();
    printf("%s %s\n", what, ffl_error_name(e));
    if (e != expected) {
        printf("%s: expected %s\n", what, ffl_error_name(expected));
        failures++;
    }
}

/* Prints the `n` floats of `pname` after the x form, and after the float form as `ref`. */
static void compare_get(const char *what, GLenum pname, int n, const GLfloat *x_state)
{
    GLfloat v[16];
    glGetFloatv(pname, v);
    printf("%s", what);
    ffl_pfv("v", x_state, n);
    printf(" ref");
    ffl_pfv("v", v, n);
    printf("\n");
}

static void lights_and_materials(void)
{
    static const GLfixed ambient[4] = { FX(0.25), FX(-0.5), FX(1.75), FX(1) };
    static const GLfixed position[4] = { FX(1.5), 0x7fffffff, (GLfixed)0x80000000, FX(0.5) };
    static const GLfixed emission[4] = { 1, -1, 32768, 65535 };
    GLfloat x_state[4], f[4];
    GLfixed back[4];
    int k;

    glLightxv(GL_LIGHT1, GL_AMBIENT, ambient);
    glGetLightfv(GL_LIGHT1, GL_AMBIENT, x_state);
    for (k = 0; k < 4; k++)
        f[k] = (GLfloat)fx(ambient[k]);
    glLightfv(GL_LIGHT1, GL_AMBIENT, f);
    glGetLightfv(GL_LIGHT1, GL_AMBIENT, f);
    printf("light ambient");
    ffl_pfv("v", x_state, 4);
    printf(" ref");
    ffl_pfv("v", f, 4);
    printf("\n");
    glGetLightxv(GL_LIGHT1, GL_AMBIENT, back);
    printf("light ambient fixed i %d %d %d %d ref i %d %d %d %d\n", (int)back[0], (int)back[1],
           (int)back[2], (int)back[3], (int)ambient[0], (int)ambient[1], (int)ambient[2],
           (int)ambient[3]);

    /* A position with the largest and smallest fixed values (w = 0.5, under identity). */
    glLightxv(GL_LIGHT2, GL_POSITION, position);
    glGetLightfv(GL_LIGHT2, GL_POSITION, x_state);
    for (k = 0; k < 4; k++)
        f[k] = (GLfloat)fx(position[k]);
    glLightfv(GL_LIGHT2, GL_POSITION, f);
    glGetLightfv(GL_LIGHT2, GL_POSITION, f);
    printf("light position");
    ffl_pfv("v", x_state, 4);
    printf(" ref");
    ffl_pfv("v", f, 4);
    printf("\n");

    glLightx(GL_LIGHT2, GL_SPOT_EXPONENT, FX(12.5));
    glGetLightfv(GL_LIGHT2, GL_SPOT_EXPONENT, x_state);
    printf("spot exponent v %g ref v 12.5\n", (double)x_state[0]);
    glLightx(GL_LIGHT2, GL_SPOT_CUTOFF, FX(-3));
    check_error("bad cutoff", GL_INVALID_VALUE);

    glMaterialxv(GL_FRONT, GL_EMISSION, emission);
    glGetMaterialfv(GL_FRONT, GL_EMISSION, x_state);
    printf("emission v %.9g %.9g %.9g %.9g ref v %.9g %.9g %.9g %.9g\n", (double)x_state[0],
           (double)x_state[1], (double)x_state[2], (double)x_state[3], fx(1), fx(-1),
           fx(32768), fx(65535));
    glGetMaterialxv(GL_FRONT, GL_EMISSION, back);
    printf("emission fixed i %d %d %d %d ref i %d %d %d %d\n", (int)back[0], (int)back[1],
           (int)back[2], (int)back[3], 1, -1, 32768, 65535);
    glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, FX(32.25));
    glGetMaterialfv(GL_BACK, GL_SHININESS, x_state);
    printf("shininess v %g ref v 32.25\n", (double)x_state[0]);

    /* Booleans and enums pass as they are. */
    glLightModelx(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    {
        GLboolean b = GL_FALSE;
        glGetBooleanv(GL_LIGHT_MODEL_TWO_SIDE, &b);
        printf("two_side b %d ref b 1\n", (int)b);
    }
    glLightModelxv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glGetFloatv(GL_LIGHT_MODEL_AMBIENT, x_state);
    for (k = 0; k < 4; k++)
        f[k] = (GLfloat)fx(ambient[k]);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, f);
    compare_get("model ambient", GL_LIGHT_MODEL_AMBIENT, 4, x_state);
}

static void matrices(void)
{
    GLfloat x_state[16];
    GLfixed m[16];
    int k;
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatex(FX(1.5), FX(-2.25), 3);
    glRotatex(FX(30), FX(0.5), FX(1), 0);
    glScalex(FX(2), FX(-0.5), FX(1.125));
    glGetFloatv(GL_MODELVIEW_MATRIX, x_state);
    glLoadIdentity();
    glTranslatef((GLfloat)fx(FX(1.5)), (GLfloat)fx(FX(-2.25)), (GLfloat)fx(3));
    glRotatef(30.0f, 0.5f, 1.0f, 0.0f);
    glScalef(2.0f, -0.5f, 1.125f);
    compare_get("modelview", GL_MODELVIEW_MATRIX, 16, x_state);
    for (k = 0; k < 16; k++)
        m[k] = FX(0.125 * (k - 7));
    glLoadMatrixx(m);
    glMultMatrixx(m);
    glGetFloatv(GL_MODELVIEW_MATRIX, x_state);
    {
        GLfloat f[16];
        for (k = 0; k < 16; k++)
            f[k] = (GLfloat)fx(m[k]);
        glLoadMatrixf(f);
        glMultMatrixf(f);
    }
    compare_get("load mult", GL_MODELVIEW_MATRIX, 16, x_state);
    glGetFixedv(GL_MODELVIEW_MATRIX, m);
    printf("fixed matrix i %d %d ref i %d %d\n", (int)m[0], (int)m[5], (int)lround(x_state[0] * 65536.0),
           (int)lround(x_state[5] * 65536.0));
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrthox(FX(-2), FX(2), FX(-1.5), FX(1.5), FX(-10), FX(10));
    glGetFloatv(GL_PROJECTION_MATRIX, x_state);
    glLoadIdentity();
    glOrthof(-2, 2, -1.5f, 1.5f, -10, 10);
    compare_get("ortho", GL_PROJECTION_MATRIX, 16, x_state);
    glLoadIdentity();
    glFrustumx(FX(-1), FX(1), FX(-1), FX(1), FX(1), FX(20));
    glGetFloatv(GL_PROJECTION_MATRIX, x_state);
    glLoadIdentity();
    glFrustumf(-1, 1, -1, 1, 1, 20);
    compare_get("frustum", GL_PROJECTION_MATRIX, 16, x_state);
    glFrustumx(FX(-1), FX(1), FX(-1), FX(1), FX(-1), FX(20));
    check_error("bad frustum", GL_INVALID_VALUE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void other_state(void)
{
    static const GLfixed plane[4] = { FX(1), FX(-0.5), 0x7fffffff, FX(-2) };
    static const GLfixed fog_color[4] = { FX(0.5), FX(2), FX(-1), FX(0.25) };
    GLfloat x_state[4];
    GLfixed fixed_plane[4];
    GLfloat float_plane[4];
    GLfixed v;
    glClipPlanex(GL_CLIP_PLANE0, plane);
    glGetClipPlanef(GL_CLIP_PLANE0, float_plane);
    glGetClipPlanex(GL_CLIP_PLANE0, fixed_plane);
    printf("clip plane v %.9g %.9g %.9g %.9g ref v %.9g %.9g %.9g %.9g\n",
           (double)float_plane[0], (double)float_plane[1], (double)float_plane[2],
           (double)float_plane[3], (double)(GLfloat)fx(plane[0]), (double)(GLfloat)fx(plane[1]),
           (double)(GLfloat)fx(plane[2]), (double)(GLfloat)fx(plane[3]));
    printf("clip plane fixed i %d %d %d ref i %d %d %d\n", (int)fixed_plane[0], (int)fixed_plane[1],
           (int)fixed_plane[3], (int)plane[0], (int)plane[1], (int)plane[3]);
    glPointSizex(FX(3.5));
    glGetFloatv(GL_POINT_SIZE, x_state);
    printf("point size v %g ref v 3.5\n", (double)x_state[0]);
    glLineWidthx(FX(2.75));
    glGetFloatv(GL_LINE_WIDTH, x_state);
    printf("line width v %g ref v 2.75\n", (double)x_state[0]);
    glFogx(GL_FOG_MODE, GL_LINEAR);
    {
        GLint mode = 0;
        glGetIntegerv(GL_FOG_MODE, &mode);
        printf("fog_mode i %d ref i %d\n", (int)mode, (int)GL_LINEAR);
    }
    glFogx(GL_FOG_DENSITY, FX(0.75));
    glGetFloatv(GL_FOG_DENSITY, x_state);
    printf("fog density v %g ref v 0.75\n", (double)x_state[0]);
    glFogxv(GL_FOG_COLOR, fog_color);
    glGetFloatv(GL_FOG_COLOR, x_state);
    printf("fog color v %g %g %g %g ref v 0.5 1 0 0.25\n", (double)x_state[0],
           (double)x_state[1], (double)x_state[2], (double)x_state[3]);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    glGetTexEnvxv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
    printf("env mode i %d ref i %d\n", (int)v, (int)GL_DECAL);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    printf("min filter i %d ref i %d\n", (int)v, (int)GL_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, FX(0.5));
    glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &v);
    printf("priority i %d ref i %d\n", (int)v, (int)FX(0.5));
    glClearColorx(FX(0.25), FX(1.5), FX(-0.5), FX(0.75));
    glGetFloatv(GL_COLOR_CLEAR_VALUE, x_state);
    printf("clear color v %g %g %g %g ref v 0.25 1 0 0.75\n", (double)x_state[0],
           (double)x_state[1], (double)x_state[2], (double)x_state[3]);
    glClearDepthx(FX(0.5));
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, x_state);
    printf("clear depth v %g ref v 0.5\n", (double)x_state[0]);
    glDepthRangex(FX(0.25), FX(2));
    glGetFloatv(GL_DEPTH_RANGE, x_state);
    printf("depth range v %g %g ref v 0.25 1\n", (double)x_state[0], (double)x_state[1]);
    glDepthRangef(0.0f, 1.0f);
    glAlphaFuncx(GL_GREATER, FX(0.5));
    glGetFloatv(GL_ALPHA_TEST_REF, x_state);
    printf("alpha_value v %g ref v 0.5\n", (double)x_state[0]);
    glPolygonOffsetx(FX(-1.5), FX(2));
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, x_state);
    printf("offset factor v %g ref v -1.5\n", (double)x_state[0]);
    glSampleCoveragex(FX(0.5), GL_TRUE);
    glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, x_state);
    printf("coverage v %g ref v 0.5\n", (double)x_state[0]);
    glGetFixedv(GL_FOG_MODE, &v);
    printf("fixed enum i %d ref i %d\n", (int)v, (int)GL_LINEAR * 65536);
    check_error("state errors", GL_NO_ERROR);
}

/* A lit vertex with the state set by the `x` commands, then by the float commands. */
static void lit_vertex(int fixed_forms, GLfloat *out)
{
    static GLfloat buf[64];
    int k;
    GLint n;
    glViewport(0, 0, 64, 64);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    if (fixed_forms) {
        static const GLfixed position[4] = { FX(1), FX(2), FX(3), 0 };
        static const GLfixed diffuse[4] = { FX(0.75), FX(0.5), FX(0.25), FX(1) };
        glLightxv(GL_LIGHT0, GL_POSITION, position);
        glMaterialxv(GL_FRONT, GL_DIFFUSE, diffuse);
        glMaterialx(GL_FRONT, GL_SHININESS, FX(10));
        glNormal3x(FX(0.25), FX(0.5), FX(1));
        glColor4x(FX(0.1), FX(0.2), FX(0.3), FX(0.4));
        glMultiTexCoord4x(GL_TEXTURE0, FX(0.5), FX(-1), 0, FX(1));
    } else {
        static const GLfloat position[4] = { 1, 2, 3, 0 };
        static const GLfloat diffuse[4] = { 0.75f, 0.5f, 0.25f, 1 };
        glLightfv(GL_LIGHT0, GL_POSITION, position);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
        glMaterialf(GL_FRONT, GL_SHININESS, 10);
        glNormal3f(0.25f, 0.5f, 1);
        glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
        glMultiTexCoord4f(GL_TEXTURE0, 0.5f, -1, 0, 1);
    }
    glFeedbackBuffer(64, GL_4D_COLOR_TEXTURE, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex3f(0.25f, -0.5f, 0.0f);
    glEnd();
    n = glRenderMode(GL_RENDER);
    for (k = 0; k < 13; k++)
        out[k] = k < n ? buf[k] : -1.0f;
}

int main(void)
{
    GLfloat x_vertex[13], f_vertex[13];
    ffl_test_init();
    lights_and_materials();
    matrices();
    other_state();
    lit_vertex(1, x_vertex);
    lit_vertex(0, f_vertex);
    printf("vertex");
    ffl_pfv("v", x_vertex, 13);
    printf(" ref");
    ffl_pfv("v", f_vertex, 13);
    printf("\n");
    return failures;
}
