/* ffl-test: differential */
/*
 * The GL 1.4 arrays (§2.8): glSecondaryColorPointer (size 3, every color type,
 * normalized as table 2.9 says) and glFogCoordPointer (float, double), their
 * enables, pointers and queries; glArrayElement makes an element's secondary
 * color and fog coordinate current; the errors of the pointer commands
 * (Mesa's order: stride, type, size). (OSMesa stores a negative stride despite
 * the error, difference 11, so nothing is queried after the errors; its
 * glInterleavedArrays leaves both arrays enabled:
 * arrays_osmesa_diff_interleaved_disables.c.)
 */
#include "ffl_test.h"

static void current(const char *what)
{
    GLfloat v[4];
    printf("%s", what);
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, v);
    ffl_pfv("secondary", v, 4);
    glGetFloatv(GL_CURRENT_FOG_COORD, v);
    ffl_pfv("fog", v, 1);
    printf(" error %s\n", ffl_error_name(glGetError()));
}

static void state(const char *what)
{
    GLint size = -1, type = -1, stride = -1, fog_type = -1, fog_stride = -1;
    GLboolean secondary_on = 2, fog_on = 2;
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &size);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &type);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &stride);
    glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &fog_type);
    glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &fog_stride);
    glGetBooleanv(GL_SECONDARY_COLOR_ARRAY, &secondary_on);
    fog_on = glIsEnabled(GL_FOG_COORD_ARRAY);
    printf("%s secondary size %d type 0x%x stride %d on %d fog type 0x%x stride %d on %d", what,
           size, type, stride, (int)secondary_on, fog_type, fog_stride, (int)fog_on);
    printf(" error %s\n", ffl_error_name(glGetError()));
}

int main(void)
{
    static const GLubyte ub[3][3] = { { 0, 128, 255 }, { 10, 20, 30 }, { 255, 0, 7 } };
    static const GLshort s[3][4] = { { -32768, 0, 32767, 99 }, { 1, 2, 3, 99 }, { 5, 6, 7, 99 } };
    static const GLfloat f[3][3] = { { 0.25f, -0.5f, 2.0f }, { 0, 0, 1 }, { 1, 0, 0 } };
    static const GLfloat fogf[3] = { 1.5f, -2.0f, 3.25f };
    static const GLdouble fogd[3][2] = { { 0.125, 9 }, { 7.5, 9 }, { -1.0, 9 } };
    static const GLfloat positions[3][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    void *pointer = NULL;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    state("initial");
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, ub);
    glFogCoordPointer(GL_FLOAT, 0, fogf);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    state("ubyte_float");
    glArrayElement(0);
    current("element0");
    glArrayElement(2);
    current("element2");
    glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &pointer);
    printf("secondary_pointer %d", pointer == (void *)ub);
    glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &pointer);
    printf(" fog_pointer %d error %s\n", pointer == (void *)fogf,
           ffl_error_name(glGetError()));

    glSecondaryColorPointer(3, GL_SHORT, 4 * sizeof(GLshort), s);
    glFogCoordPointer(GL_DOUBLE, 2 * sizeof(GLdouble), fogd);
    state("short_double");
    glArrayElement(1);
    current("element1");
    glArrayElement(0);
    current("element0");
    glSecondaryColorPointer(3, GL_FLOAT, 0, f);
    glBegin(GL_POINTS);
    glArrayElement(0);
    glEnd();
    current("float_inside_begin_end");
    glEnableClientState(GL_VERTEX_ARRAY);
    glDrawArrays(GL_POINTS, 0, 3);
    printf("draw error %s\n", ffl_error_name(glGetError()));

    glSecondaryColorPointer(3, GL_FLOAT, -1, f);
    printf("secondary_negative_stride error %s\n", ffl_error_name(glGetError()));
    glSecondaryColorPointer(3, 0x1234, 0, f);
    printf("secondary_bad_type error %s\n", ffl_error_name(glGetError()));
    glSecondaryColorPointer(2, GL_FLOAT, 0, f);
    printf("secondary_size_2 error %s\n", ffl_error_name(glGetError()));
    glFogCoordPointer(GL_FLOAT, -4, fogf);
    printf("fog_negative_stride error %s\n", ffl_error_name(glGetError()));
    glFogCoordPointer(GL_INT, 0, fogf);
    printf("fog_bad_type error %s\n", ffl_error_name(glGetError()));
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    glDisableClientState(GL_FOG_COORD_ARRAY);
    printf("disabled %d %d error %s\n", (int)glIsEnabled(GL_SECONDARY_COLOR_ARRAY),
           (int)glIsEnabled(GL_FOG_COORD_ARRAY), ffl_error_name(glGetError()));
    return 0;
}
