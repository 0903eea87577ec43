/* ffl-test: differential */
/*
 * Line primitives (§2.6.1): GL_LINES, GL_LINE_STRIP and GL_LINE_LOOP in
 * feedback (GL_3D_COLOR), smooth-shaded with a color per vertex, lit and
 * unlit. GL_LINES with an odd count drops the last vertex; a strip or loop
 * of one vertex makes nothing; a loop of two vertices is the segment there
 * and back; the loop closes from the last vertex to the first. Each glBegin
 * is marked by a glPassThrough (ffl_fb_begin) so every segment is printed
 * with the token the spec gives it (line-prim=...).
 *
 * osmesa-known: line-reset
 * (OSMesa feeds back GL_LINE_TOKEN where the spec resets the stipple: every
 * segment of GL_LINES, the first of each strip and loop; see
 * docs/osmesa-differences.md.)
 */
#include "ffl_test.h"

#define BUF_SIZE 2048

static void vertex(int k)
{
    /* a zigzag with colors varying along it */
    glColor4f(0.1f * (float)(k % 10), 1.0f - 0.07f * (float)k, 0.5f, 1.0f - 0.05f * (float)k);
    glNormal3f(0.2f * (float)(k % 3), 0.1f, 1.0f);
    glVertex3f(-8.0f + 1.5f * (float)k, (k % 2) ? 3.0f : -2.5f, -0.5f * (float)(k % 4));
}

static void draw(ffl_fb *fb, GLenum mode, int count)
{
    int k;
    ffl_fb_begin(fb, mode);
    for (k = 0; k < count; k++)
        vertex(k);
    glEnd();
}

static int pass(const char *tag)
{
    static const GLenum modes[3] = { GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP };
    static const int counts[] = { 0, 1, 2, 3, 4, 7 };
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    int m, c;
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    for (m = 0; m < 3; m++)
        for (c = 0; c < (int)(sizeof counts / sizeof counts[0]); c++)
            draw(&fb, modes[m], counts[c]);
    return ffl_fb_finish(&fb, tag, NULL, NULL);
}

int main(void)
{
    static const GLfloat light_position[4] = { 1, 2, 3, 0 };
    int failed = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(20, 0, 0, 1);

    failed |= pass("unlit");

    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHTING);
    glEnable(GL_COLOR_MATERIAL);
    failed |= pass("lit");
    return failed;
}
