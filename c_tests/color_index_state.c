/* ffl-test: differential */
/*
 * The current color index and the index array (§2.7, §2.8) in RGBA mode:
 * every glIndex form sets GL_CURRENT_INDEX (converted directly, not
 * normalized), glIndexPointer's state and errors, glArrayElement makes an
 * element's index current, and nothing else changes: lit and fed-back colors
 * are the same with and without an index array.
 */
#include "ffl_test.h"

static void current(const char *what)
{
    GLfloat index = -1;
    glGetFloatv(GL_CURRENT_INDEX, &index);
    printf("%s index %g error %s\n", what, index, ffl_error_name(glGetError()));
}

int main(void)
{
    static const GLdouble d = 2.5;
    static const GLfloat f = 3.25f;
    static const GLint i = 7;
    static const GLshort s = -4;
    static const GLubyte ub = 200;
    static const GLshort indices[3] = { 11, 12, 13 };
    static const GLfloat positions[3][3] = { { 0, 0, 0 }, { 0.5f, 0, 0 }, { 0, 0.5f, 0 } };
    GLint type = -1, stride = -1;
    GLfloat feedback[128];
    GLint n, k;
    void *pointer = NULL;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    current("initial");
    glIndexd(1.5);
    current("d");
    glIndexdv(&d);
    current("dv");
    glIndexf(-0.75f);
    current("f");
    glIndexfv(&f);
    current("fv");
    glIndexi(9);
    current("i");
    glIndexiv(&i);
    current("iv");
    glIndexs(-3);
    current("s");
    glIndexsv(&s);
    current("sv");
    glIndexub(255);
    current("ub");
    glIndexubv(&ub);
    current("ubv");

    glIndexPointer(GL_SHORT, 0, indices);
    glEnableClientState(GL_INDEX_ARRAY);
    glGetIntegerv(GL_INDEX_ARRAY_TYPE, &type);
    glGetIntegerv(GL_INDEX_ARRAY_STRIDE, &stride);
    glGetPointerv(GL_INDEX_ARRAY_POINTER, &pointer);
    printf("array type 0x%x stride %d pointer %d enabled %d error %s\n", type, stride,
           pointer == (void *)indices, (int)glIsEnabled(GL_INDEX_ARRAY),
           ffl_error_name(glGetError()));
    glArrayElement(1);
    current("element1");

    glVertexPointer(3, GL_FLOAT, 0, positions);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(0.25f, 0.5f, 0.75f);
    glFeedbackBuffer(128, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_POINTS, 0, 3);
    n = glRenderMode(GL_RENDER);
    printf("draw values %d:", (int)n);
    for (k = 0; k < n; k++) {
        printf(" %.9g", feedback[k]);
    }
    printf(" error %s\n", ffl_error_name(glGetError()));

    glIndexPointer(0x1234, 0, indices);
    printf("bad_type error %s\n", ffl_error_name(glGetError()));
    glIndexPointer(GL_BYTE, 0, indices);
    printf("byte_type error %s\n", ffl_error_name(glGetError()));
    glInterleavedArrays(GL_V3F, 0, positions);
    printf("interleaved enabled %d error %s\n", (int)glIsEnabled(GL_INDEX_ARRAY),
           ffl_error_name(glGetError()));
    return 0;
}
