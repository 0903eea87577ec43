/* ffl-test: differential */
/*
 * Feedback buffer overflow (§5.3): when the values do not fit, glRenderMode
 * returns -1 and nothing is written past the buffer's end (a guard region
 * after it must stay untouched). Buffers ending at a token, in the middle
 * of a vertex and exactly at the end of the data; then an ordinary pass to
 * show the overflow left nothing behind. Every value written is printed
 * (what an overflowing buffer holds is the values that fit, in order).
 */
#include "ffl_test.h"

#define GUARD 32
#define SENTINEL -4242.0f

static void draw(void)
{
    int k;
    glPassThrough(9.0f);
    glBegin(GL_POINTS);
    for (k = 0; k < 5; k++) {
        glColor4f(0.1f * (float)k, 0.2f, 0.3f, 1.0f);
        glVertex3f((float)k - 2.0f, 0.5f * (float)k, 0);
    }
    glEnd();
}

/* 2 (pass-through) + 5 points of 8 values (GL_3D_COLOR) = 42 values */
#define TOTAL 42

static int run(GLsizei size)
{
    GLfloat buf[TOTAL + GUARD];
    GLint n;
    int k, guard_ok = 1, untouched = 0;
    for (k = 0; k < TOTAL + GUARD; k++)
        buf[k] = SENTINEL;
    glFeedbackBuffer(size, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    n = glRenderMode(GL_RENDER);
    for (k = size; k < TOTAL + GUARD; k++)
        if (buf[k] != SENTINEL)
            guard_ok = 0;
    for (k = 0; k < size; k++)
        if (buf[k] == SENTINEL)
            untouched++;
    printf("size %d return %d guard_intact %d untouched_in_buffer %d\n", (int)size, (int)n,
           guard_ok, untouched);
    printf("size %d values", (int)size);
    for (k = 0; k < size; k++)
        ffl_pf(buf[k]);
    printf("\n");
    printf("size %d error %s\n", (int)size, ffl_error_name(glGetError()));
    return guard_ok ? 0 : 1;
}

int main(void)
{
    static const GLsizei sizes[] = { 1, 2, 5, 10, 17, 41, 42, 43 };
    int i, failed = 0;
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (i = 0; i < (int)(sizeof sizes / sizeof sizes[0]); i++)
        failed |= run(sizes[i]);
    return failed;
}
