/* ffl-test: differential */
/*
 * glCallLists (§5.4) with every type of its name array (GL_BYTE,
 * GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT,
 * GL_FLOAT truncated, GL_2_BYTES, GL_3_BYTES, GL_4_BYTES big-endian) and
 * glListBase, negative offsets included; names without a list are skipped;
 * glListBase and glCallLists compiled into a list (the base in force when the
 * list executes counts). Lists 1..8 each pass a distinct token through
 * feedback, so the tokens show which lists ran, in order.
 */
#include "ffl_test.h"

static GLfloat fb[256];

static void start(void)
{
    glFeedbackBuffer(256, GL_2D, fb);
    glRenderMode(GL_FEEDBACK);
}

static void finish(const char *what)
{
    GLint n = glRenderMode(GL_RENDER);
    GLint base = -7;
    ffl_print_feedback(what, fb, n, GL_2D);
    glGetIntegerv(GL_LIST_BASE, &base);
    printf("%s count %d base %d\n", what, (int)n, (int)base);
    ffl_print_error(what);
}

int main(void)
{
    static const GLbyte bytes[] = { 1, 3, -1, 2 };
    static const GLubyte ubytes[] = { 4, 1, 200 };
    static const GLshort shorts[] = { 2, -3, 8 };
    static const GLushort ushorts[] = { 7, 1, 65535 };
    static const GLint ints[] = { 5, -10, 6 };
    static const GLuint uints[] = { 8, 2, 4000000000u };
    static const GLfloat floats[] = { 1.9f, 3.2f, -0.7f, 7.99f };
    static const GLubyte two[] = { 0, 3, 0, 6, 1, 1 };
    static const GLubyte three[] = { 0, 0, 2, 0, 0, 5, 0, 1, 0 };
    static const GLubyte four[] = { 0, 0, 0, 8, 0, 0, 0, 1, 1, 0, 0, 0 };
    GLuint k;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    for (k = 1; k <= 8; k++) {
        glNewList(k, GL_COMPILE);
        glPassThrough((GLfloat)k);
        glEndList();
    }
    glNewList(1 + 256, GL_COMPILE);
    glPassThrough(257.0f);
    glEndList();

    start();
    glCallLists(4, GL_BYTE, bytes);
    finish("byte");
    start();
    glCallLists(3, GL_UNSIGNED_BYTE, ubytes);
    finish("unsigned_byte");
    start();
    glCallLists(3, GL_SHORT, shorts);
    finish("short");
    start();
    glCallLists(3, GL_UNSIGNED_SHORT, ushorts);
    finish("unsigned_short");
    start();
    glCallLists(3, GL_INT, ints);
    finish("int");
    start();
    glCallLists(3, GL_UNSIGNED_INT, uints);
    finish("unsigned_int");
    start();
    glCallLists(4, GL_FLOAT, floats);
    finish("float");
    start();
    glCallLists(3, GL_2_BYTES, two);
    finish("2_bytes");
    start();
    glCallLists(3, GL_3_BYTES, three);
    finish("3_bytes");
    start();
    glCallLists(3, GL_4_BYTES, four);
    finish("4_bytes");

    /* A base: the offsets are added to it (negative ones too). */
    glListBase(3);
    start();
    glCallLists(4, GL_BYTE, bytes);
    finish("byte_base_3");
    start();
    glCallLists(3, GL_INT, ints);
    finish("int_base_3");
    glListBase(10);
    start();
    glCallLists(3, GL_SHORT, shorts);
    finish("short_base_10");
    start();
    glCallLists(0, GL_SHORT, shorts);
    finish("none");

    /* Compiled: the offsets are read at compile time, the base at execution. */
    glListBase(0);
    {
        GLint names[3] = { 1, 2, 3 };
        glNewList(20, GL_COMPILE);
        glCallLists(3, GL_INT, names);
        glListBase(4);
        glCallLists(3, GL_INT, names);
        glEndList();
        names[0] = 8;
        names[1] = 8;
        names[2] = 8;
    }
    start();
    glCallList(20);
    finish("compiled_first_call");
    start();
    glCallList(20);
    finish("compiled_second_call");
    return 0;
}
