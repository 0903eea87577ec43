/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: GL_LINE_RESET_TOKEN for line primitives (§3.4.2,
 * §5.3). The line stipple counter is reset before every segment of
 * GL_LINES and when glBegin starts a GL_LINE_STRIP or GL_LINE_LOOP, and
 * feedback returns GL_LINE_RESET_TOKEN whenever the stipple is reset: every
 * segment of GL_LINES, the first of each strip and loop; GL_LINE_TOKEN for
 * the others. Mesa's draw module (line stipple disabled) feeds back
 * GL_LINE_TOKEN for every segment of a line primitive. The outline of a
 * polygon in GL_LINE mode starts with GL_LINE_RESET_TOKEN in both (shown for
 * contrast). Every segment is printed with the token the spec gives it
 * (line-prim=..., checked on the fflight build), and the counts of reset
 * tokens with the spec's count.
 */
#include "ffl_test.h"

#define BUF_SIZE 2048

static void vertices(int n)
{
    int k;
    for (k = 0; k < n; k++) {
        glColor3f(0.1f * (float)k, 0.5f, 1.0f - 0.1f * (float)k);
        glVertex2f(-8.0f + 3.0f * (float)k, (k % 2) ? 4.0f : -3.0f);
    }
}

int main(void)
{
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    int failed;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D);
    ffl_fb_begin(&fb, GL_LINES); /* 3 segments: 3 resets */
    vertices(6);
    glEnd();
    ffl_fb_begin(&fb, GL_LINE_STRIP); /* 4 segments: 1 reset */
    vertices(5);
    glEnd();
    ffl_fb_begin(&fb, GL_LINE_LOOP); /* 4 segments: 1 reset */
    vertices(4);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    ffl_fb_begin(&fb, GL_TRIANGLES); /* an outline: 1 reset in both */
    vertices(3);
    glEnd();
    failed = ffl_fb_finish(&fb, "lines", NULL, NULL);
    printf("line_primitives reset_tokens %ld ref reset_tokens 5\n", fb.counts.line_resets - 1);
    printf("line_primitives segment_tokens %ld ref segment_tokens 11\n",
           fb.counts.lines + fb.counts.line_resets - 3);
    return failed;
}
