/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: a pointer command with a negative stride.
 *
 * A negative stride is GL_INVALID_VALUE (§2.8), and a command that raises an
 * error is ignored (§2.5): the array keeps its size, type, stride and pointer.
 * Mesa records the error but, when the size and type are valid, stores the
 * call anyway (its stride check does not stop the update), so the queried
 * stride becomes negative and the type and size change.
 *
 * Here: glVertexPointer(2, GL_SHORT, 6, p), then glVertexPointer(3, GL_FLOAT,
 * -4, q); the same for the color and texture coordinate arrays.
 */
#include "ffl_test.h"

static void show(const char *what, GLenum size, GLenum type, GLenum stride, int want_size,
                 GLenum want_type, int want_stride)
{
    GLint s = -99, t = -99, st = -99;
    glGetIntegerv(size, &s);
    glGetIntegerv(type, &t);
    glGetIntegerv(stride, &st);
    printf("%s error %s size %d type %d stride %d ref size %d type %d stride %d\n", what,
           ffl_error_name(glGetError()), (int)s, (int)t, (int)st, want_size, (int)want_type,
           want_stride);
}

int main(void)
{
    static const GLshort p[16] = { 0 };
    static const GLfloat q[16] = { 0 };

    ffl_test_init();
    glVertexPointer(2, GL_SHORT, 6, p);
    glVertexPointer(3, GL_FLOAT, -4, q);
    show("vertex", GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, 2,
         GL_SHORT, 6);
    glColorPointer(3, GL_SHORT, 6, p);
    glColorPointer(4, GL_FLOAT, -4, q);
    show("color", GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, 3, GL_SHORT,
         6);
    glTexCoordPointer(1, GL_SHORT, 2, p);
    glTexCoordPointer(4, GL_FLOAT, -16, q);
    show("texcoord", GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
         GL_TEXTURE_COORD_ARRAY_STRIDE, 1, GL_SHORT, 2);
    return 0;
}
