/* ffl-test: differential */
/*
 * Integer forms and conversions (§2.7, table 2.9, §6.1.2): glLightiv and
 * glMaterialiv map colors linearly from the full int range, (2c + 1) /
 * (2^32 - 1), and take positions, directions, exponents, cutoffs and
 * attenuations as they are; glGetLightiv / glGetMaterialiv map colors back
 * and round other values (chosen so that rounding and truncation agree); glNormal3b/s/i and their v forms map signed
 * integers the same way for their width; glColor in every integer type,
 * signed and unsigned. Values are read back through glGet*fv / glGet*iv and
 * through feedback (lighting off for colors, on for normals).
 */
#include "ffl_test.h"
#include <limits.h>

static void get_light(const char *what, GLenum light, GLenum pname, int n)
{
    GLfloat f[4] = { -9, -9, -9, -9 };
    GLint iv[4] = { -9, -9, -9, -9 };
    int k;
    glGetLightfv(light, pname, f);
    glGetLightiv(light, pname, iv);
    printf("light %s", what);
    ffl_pfv("f", f, n);
    printf(" i");
    for (k = 0; k < n; k++)
        printf(" %d", (int)iv[k]);
    printf("\n");
}

static void get_material(const char *what, GLenum face, GLenum pname, int n)
{
    GLfloat f[4] = { -9, -9, -9, -9 };
    GLint iv[4] = { -9, -9, -9, -9 };
    int k;
    glGetMaterialfv(face, pname, f);
    glGetMaterialiv(face, pname, iv);
    printf("material %s", what);
    ffl_pfv("f", f, n);
    printf(" i");
    for (k = 0; k < n; k++)
        printf(" %d", (int)iv[k]);
    printf("\n");
}

/* Draws one point per call of `emit` (0..count-1) and prints the buffer. */
static int feedback_points(const char *tag, void (*emit)(int), int count)
{
    GLfloat buf[8 * 32];
    GLint n;
    int k;
    glFeedbackBuffer(8 * 32, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    for (k = 0; k < count; k++) {
        emit(k);
        glVertex3f((float)k, 0, 0);
    }
    glEnd();
    n = glRenderMode(GL_RENDER);
    return ffl_print_feedback(tag, buf, n, GL_3D_COLOR);
}

static void emit_color(int k)
{
    static const GLbyte b[4] = { -128, -1, 0, 127 };
    static const GLubyte ub[4] = { 0, 1, 128, 255 };
    static const GLshort s[4] = { -32768, -1, 1000, 32767 };
    static const GLushort us[4] = { 0, 1, 32768, 65535 };
    static const GLint i[4] = { INT_MIN, -1, 123456789, INT_MAX };
    static const GLuint ui[4] = { 0u, 1u, 2147483648u, 4294967295u };
    switch (k) {
    case 0: glColor4b(b[3], b[2], b[1], b[3]); break;
    case 1: glColor4bv(b); break;
    case 2: glColor3b(64, 32, 127); break;
    case 3: glColor4ub(ub[3], ub[2], ub[1], ub[3]); break;
    case 4: glColor4ubv(ub); break;
    case 5: glColor3ub(200, 100, 50); break;
    case 6: glColor4s(s[3], s[2], s[1], s[3]); break;
    case 7: glColor4sv(s); break;
    case 8: glColor4us(us[3], us[2], us[1], us[3]); break;
    case 9: glColor4usv(us); break;
    case 10: glColor4i(i[3], i[2], i[1], i[3]); break;
    case 11: glColor4iv(i); break;
    case 12: glColor4ui(ui[3], ui[2], ui[1], ui[3]); break;
    case 13: glColor4uiv(ui); break;
    case 14: glColor3i(INT_MAX / 2, INT_MAX / 4, 0); break;
    case 15: glColor3us(65535, 32767, 1); break;
    default: glColor4d(0.125, 0.25, 0.5, 0.75); break;
    }
}

static void emit_normal(int k)
{
    static const GLbyte b[3] = { 50, -70, 100 };
    static const GLshort s[3] = { 10000, -20000, 30000 };
    static const GLint i[3] = { 1000000000, -300000000, 2000000000 };
    switch (k) {
    case 0: glNormal3b(0, 0, 127); break;
    case 1: glNormal3b(60, -20, 90); break;
    case 2: glNormal3bv(b); break;
    case 3: glNormal3s(0, 12000, 25000); break;
    case 4: glNormal3sv(s); break;
    case 5: glNormal3i(0, 0, INT_MAX); break;
    case 6: glNormal3i(500000000, 0, 1500000000); break;
    case 7: glNormal3iv(i); break;
    case 8: glNormal3b(-128, 0, 0); break;
    default: glNormal3d(0.25, 0.5, 0.75); break;
    }
}

int main(void)
{
    /* no negative colors and no fractions of .5 or more in what glGet*iv
     * reads back: there Mesa truncates where the spec rounds (see
     * osmesa_diff_get_integer.c); negative integer colors are tested
     * through glColor below */
    static const GLint color_i[4] = { INT_MAX, 0, INT_MAX / 3, INT_MAX / 2 };
    static const GLint color2_i[4] = { INT_MAX / 4, 7, 1000, INT_MAX };
    static const GLint position_i[4] = { 3, -4, 12, 1 };
    static const GLint direction_i[3] = { 0, -1, -2 };
    static const GLint material_i[4] = { INT_MAX / 4, INT_MAX / 2, INT_MAX / 8, INT_MAX };
    int failed = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-20, 20, -20, 20, -20, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* glLightiv / glLighti, read back both ways */
    glLightiv(GL_LIGHT1, GL_DIFFUSE, color_i);
    get_light("diffuse", GL_LIGHT1, GL_DIFFUSE, 4);
    glLightiv(GL_LIGHT1, GL_AMBIENT, color2_i);
    get_light("ambient", GL_LIGHT1, GL_AMBIENT, 4);
    glTranslatef(1, 2, 3);
    glLightiv(GL_LIGHT1, GL_POSITION, position_i);
    get_light("position", GL_LIGHT1, GL_POSITION, 4);
    glRotatef(90, 0, 0, 1);
    glLightiv(GL_LIGHT1, GL_SPOT_DIRECTION, direction_i);
    get_light("spot_direction", GL_LIGHT1, GL_SPOT_DIRECTION, 3);
    glLoadIdentity();
    glLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 17);
    get_light("spot_exponent", GL_LIGHT1, GL_SPOT_EXPONENT, 1);
    glLighti(GL_LIGHT1, GL_SPOT_CUTOFF, 33);
    get_light("spot_cutoff", GL_LIGHT1, GL_SPOT_CUTOFF, 1);
    glLighti(GL_LIGHT1, GL_LINEAR_ATTENUATION, 2);
    get_light("linear_attenuation", GL_LIGHT1, GL_LINEAR_ATTENUATION, 1);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.25f);
    get_light("quadratic_attenuation_0.25", GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 1);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.25f);
    get_light("spot_exponent_2.25", GL_LIGHT1, GL_SPOT_EXPONENT, 1);
    get_light("default_light0_diffuse", GL_LIGHT0, GL_DIFFUSE, 4);

    /* glMaterialiv / glMateriali */
    glMaterialiv(GL_FRONT, GL_AMBIENT, material_i);
    get_material("front_ambient", GL_FRONT, GL_AMBIENT, 4);
    glMaterialiv(GL_BACK, GL_EMISSION, color_i);
    get_material("back_emission", GL_BACK, GL_EMISSION, 4);
    glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, 37);
    get_material("shininess", GL_FRONT, GL_SHININESS, 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.75f);
    get_material("shininess_12.75", GL_FRONT, GL_SHININESS, 1);
    glMaterialf(GL_FRONT, GL_SHININESS, 12.25f);
    get_material("shininess_12.25", GL_FRONT, GL_SHININESS, 1);
    get_material("default_front_diffuse", GL_FRONT, GL_DIFFUSE, 4);

    /* integer colors, lighting off: the fed-back color is the converted
     * current color, clamped */
    failed |= feedback_points("color", emit_color, 17);

    /* integer normals, lighting on: a directional light along +z, so the
     * diffuse term is the normal's z (no GL_NORMALIZE) */
    {
        static const GLfloat light_pos[4] = { 0, 0, 1, 0 };
        static const GLfloat dim[4] = { 0.5f, 0.5f, 0.5f, 1 };
        static const GLfloat black[4] = { 0, 0, 0, 1 };
        static const GLfloat white[4] = { 1, 1, 1, 1 };
        glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, dim);
        glLightfv(GL_LIGHT0, GL_SPECULAR, black);
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
        glMaterialfv(GL_FRONT, GL_AMBIENT, black);
        glMaterialfv(GL_FRONT, GL_EMISSION, black);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
        glEnable(GL_LIGHT0);
        glEnable(GL_LIGHTING);
        failed |= feedback_points("normal", emit_normal, 10);
        glEnable(GL_NORMALIZE);
        failed |= feedback_points("normal_normalized", emit_normal, 10);
    }
    printf("error %s\n", ffl_error_name(glGetError()));
    return failed;
}
