/* ffl-test: differential */
/*
 * Selection buffer overflow (§5.2): the same three hit records (3, 4 and 6 values)
 * with buffers of every size from 1 to 14 (an empty one: select_osmesa_diff.c); glRenderMode returns -1 whenever they do
 * not all fit, what fits is written, and nothing past the buffer's size (sentinels
 * after it stay). Then a pass after an overflow starts from an empty buffer.
 */
#include "ffl_test.h"

#define SENTINEL 0xDEADBEEFu

static void point(float z)
{
    glBegin(GL_POINTS);
    glVertex3f(0.25f, -0.25f, z);
    glEnd();
}

static void records(void)
{
    glInitNames();
    point(0.5f);
    glPushName(7);
    point(-0.25f);
    point(0.75f);
    glPushName(8);
    glPushName(9);
    glPushName(10);
    point(0.0f);
}

int main(void)
{
    GLuint buf[24];
    GLsizei size;
    int bad = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    for (size = 1; size <= 14; size++) {
        GLint hits, i, intact = 1;
        for (i = 0; i < 24; i++)
            buf[i] = SENTINEL;
        glSelectBuffer(size, buf);
        glRenderMode(GL_SELECT);
        records();
        hits = glRenderMode(GL_RENDER);
        printf("size %d\n", (int)size);
        bad |= ffl_print_hits("  select", buf, hits, size);
        for (i = size; i < 24; i++)
            intact &= buf[i] == SENTINEL;
        printf("  past_the_buffer %s\n", intact ? "untouched" : "WRITTEN");
    }
    /* After an overflow the next pass starts empty. */
    glSelectBuffer(3, buf);
    glRenderMode(GL_SELECT);
    records();
    printf("overflowed %d\n", (int)glRenderMode(GL_RENDER));
    glRenderMode(GL_SELECT);
    point(0.5f); /* an empty name stack: a record of 3 values fits */
    bad |= ffl_print_hits("again", buf, glRenderMode(GL_RENDER), 3);
    ffl_print_error("after");
    return bad;
}
