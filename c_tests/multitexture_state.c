/* ffl-test: differential */
/*
 * Multitexture state (GL 1.3, §2.7, §2.8, §2.11.2) and texture coordinate generation state
 * (§2.11.4), read back: each unit's current texture coordinates (glMultiTexCoord in every
 * form), texture matrix and stack depth, coordinate generation modes and planes (the eye
 * plane as GL stores it, in eye coordinates) and enables; the client active unit's texture
 * coordinate array state; and the errors of bad coordinates, pnames, modes and units.
 */
#include "ffl_test.h"

static const GLshort short_coords[4] = { 3, -4, 5, 2 };
static const GLint int_coords[4] = { -7, 8, 9, -1 };
static const GLfloat float_coords[4] = { 0.25f, -0.5f, 0.75f, 2.0f };
static const GLdouble double_coords[4] = { 1.5, 2.5, -3.5, 0.5 };

static void print_unit_coords(const char *what)
{
    int unit;
    for (unit = 0; unit < 4; unit++) {
        char label[64];
        glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        sprintf(label, "%s unit%d", what, unit);
        ffl_print_floats(label, GL_CURRENT_TEXTURE_COORDS, 4);
    }
    glActiveTexture(GL_TEXTURE0);
}

static void multi_tex_coords(void)
{
    glMultiTexCoord1s(GL_TEXTURE1, 3);
    glMultiTexCoord2i(GL_TEXTURE2, -7, 8);
    glMultiTexCoord3f(GL_TEXTURE3, 0.25f, -0.5f, 0.75f);
    print_unit_coords("scalar123");
    glMultiTexCoord4d(GL_TEXTURE0, 1.5, 2.5, -3.5, 0.5);
    glMultiTexCoord4sv(GL_TEXTURE1, short_coords);
    glMultiTexCoord3iv(GL_TEXTURE2, int_coords);
    glMultiTexCoord2fv(GL_TEXTURE3, float_coords);
    print_unit_coords("vector");
    glMultiTexCoord1dv(GL_TEXTURE0, double_coords);
    glMultiTexCoord4f(GL_TEXTURE1, 9, 8, 7, 6);
    glMultiTexCoord4i(GL_TEXTURE2, 1, 2, 3, 4);
    glMultiTexCoord2d(GL_TEXTURE3, -1, -2);
    print_unit_coords("scalar4");
    /* glTexCoord is unit 0's, whichever unit is active. */
    glActiveTexture(GL_TEXTURE2);
    glTexCoord2f(0.5f, 0.125f);
    print_unit_coords("texcoord");
    /* Inside glBegin/glEnd. */
    glBegin(GL_POINTS);
    glMultiTexCoord3s(GL_TEXTURE3, 1, 2, 3);
    glEnd();
    print_unit_coords("begin_end");
    ffl_print_error("multi_tex_coord");
}

static void texture_matrices(void)
{
    int unit;
    glMatrixMode(GL_TEXTURE);
    for (unit = 0; unit < 3; unit++) {
        glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        glLoadIdentity();
        glTranslatef((float)unit, 0.5f, 0.0f);
        if (unit > 0)
            glPushMatrix();
        glScalef(1.0f + (float)unit, 2.0f, 0.5f);
    }
    for (unit = 0; unit < 3; unit++) {
        char label[64];
        glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        sprintf(label, "matrix unit%d", unit);
        ffl_print_floats(label, GL_TEXTURE_MATRIX, 16);
        sprintf(label, "depth unit%d", unit);
        ffl_print_ints(label, GL_TEXTURE_STACK_DEPTH, 1);
    }
    glActiveTexture(GL_TEXTURE1);
    glPopMatrix();
    ffl_print_floats("popped unit1", GL_TEXTURE_MATRIX, 16);
    ffl_print_ints("popped depth unit1", GL_TEXTURE_STACK_DEPTH, 1);
    glActiveTexture(GL_TEXTURE0);
    ffl_print_ints("depth unit0 after", GL_TEXTURE_STACK_DEPTH, 1);
    glMatrixMode(GL_MODELVIEW);
    ffl_print_error("texture_matrices");
}

static void print_tex_gen(const char *what, GLenum coord)
{
    GLfloat plane[4];
    GLint mode = -1;
    GLdouble dplane[4];
    glGetTexGeniv(coord, GL_TEXTURE_GEN_MODE, &mode);
    printf("%s mode 0x%x\n", what, (unsigned)mode);
    glGetTexGenfv(coord, GL_OBJECT_PLANE, plane);
    printf("%s", what);
    ffl_pfv("object", plane, 4);
    printf("\n");
    glGetTexGendv(coord, GL_EYE_PLANE, dplane);
    printf("%s", what);
    ffl_pdv("eye", dplane, 4);
    printf("\n");
}

static void tex_gen_state(void)
{
    static const GLfloat plane[4] = { 1.5f, -2.0f, 0.5f, 3.0f };
    static const GLint iplane[4] = { 2, -3, 4, 1 };
    static const GLdouble dplane[4] = { 0.25, 0.5, -1.0, 2.0 };
    GLint iv[4];
    print_tex_gen("initial s", GL_S);
    print_tex_gen("initial t", GL_T);
    print_tex_gen("initial r", GL_R);
    print_tex_gen("initial q", GL_Q);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(1.0f, -2.0f, 0.5f);
    glRotatef(35.0f, 0.2f, 1.0f, 0.4f);
    glScalef(2.0f, 0.5f, 1.25f);
    glActiveTexture(GL_TEXTURE1);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenf(GL_T, GL_TEXTURE_GEN_MODE, (GLfloat)GL_SPHERE_MAP);
    glTexGend(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
    glTexGeniv(GL_T, GL_EYE_PLANE, iplane);
    glTexGeniv(GL_T, GL_OBJECT_PLANE, iplane);
    glTexGendv(GL_Q, GL_EYE_PLANE, dplane);
    glTexGenfv(GL_R, GL_EYE_PLANE, plane);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_R);
    glLoadIdentity();
    print_tex_gen("unit1 s", GL_S);
    print_tex_gen("unit1 t", GL_T);
    print_tex_gen("unit1 r", GL_R);
    print_tex_gen("unit1 q", GL_Q);
    /* Integer queries of planes that are integers (a transformed plane's rounding differs
     * in OSMesa: texgen_osmesa_diff_modes.c). */
    glGetTexGeniv(GL_T, GL_OBJECT_PLANE, iv);
    printf("unit1 t object_int %d %d %d %d\n", (int)iv[0], (int)iv[1], (int)iv[2], (int)iv[3]);
    ffl_print_bools("unit1 gen_s", GL_TEXTURE_GEN_S, 1, 1);
    ffl_print_bools("unit1 gen_t", GL_TEXTURE_GEN_T, 1, 1);
    ffl_print_bools("unit1 gen_r", GL_TEXTURE_GEN_R, 1, 1);
    glActiveTexture(GL_TEXTURE0);
    print_tex_gen("unit0 s", GL_S);
    ffl_print_bools("unit0 gen_s", GL_TEXTURE_GEN_S, 1, 1);
    ffl_print_error("tex_gen");
    /* Errors: nothing changes. */
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    ffl_print_error("sphere map for r");
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    ffl_print_error("normal map for q");
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    ffl_print_error("reflection map for q");
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_LINEAR);
    ffl_print_error("bad mode");
    glTexGeni(GL_S + 4, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    ffl_print_error("bad coord");
    glTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, plane);
    ffl_print_error("bad pname");
    glGetTexGenfv(GL_S, GL_TEXTURE_ENV_MODE, (GLfloat *)iv);
    ffl_print_error("get bad pname");
    glBegin(GL_POINTS);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnd();
    ffl_print_error("in begin/end");
    print_tex_gen("after errors s", GL_S);
    print_tex_gen("after errors q", GL_Q);
}

static void client_arrays(void)
{
    static GLshort coords[16];
    static GLfloat more[16];
    GLvoid *pointer = NULL;
    glClientActiveTexture(GL_TEXTURE2);
    ffl_print_ints("client active", GL_CLIENT_ACTIVE_TEXTURE, 1);
    glTexCoordPointer(2, GL_SHORT, 8, coords);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    ffl_print_bools("unit2 array", GL_TEXTURE_COORD_ARRAY, 1, 1);
    ffl_print_ints("unit2 size", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    ffl_print_ints("unit2 type", GL_TEXTURE_COORD_ARRAY_TYPE, 1);
    ffl_print_ints("unit2 stride", GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
    glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
    printf("unit2 pointer %d\n", pointer == (GLvoid *)coords);
    glClientActiveTexture(GL_TEXTURE0);
    glTexCoordPointer(3, GL_FLOAT, 0, more);
    ffl_print_bools("unit0 array", GL_TEXTURE_COORD_ARRAY, 1, 1);
    ffl_print_ints("unit0 size", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
    printf("unit0 pointer %d\n", pointer == (GLvoid *)more);
    glClientActiveTexture(GL_TEXTURE2);
    ffl_print_ints("unit2 size again", GL_TEXTURE_COORD_ARRAY_SIZE, 1);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    ffl_print_bools("unit2 disabled", GL_TEXTURE_COORD_ARRAY, 1, 1);
    glClientActiveTexture(GL_TEXTURE0);
    ffl_print_error("client arrays");
}

int main(void)
{
    GLint units = 0;
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    printf("enough units %d\n", units >= 4);
    ffl_print_ints("active", GL_ACTIVE_TEXTURE, 1);
    ffl_print_ints("client active", GL_CLIENT_ACTIVE_TEXTURE, 1);
    multi_tex_coords();
    texture_matrices();
    tex_gen_state();
    client_arrays();
    return 0;
}
