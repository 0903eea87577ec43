/* ffl-test: differential */
/*
 * Feedback of points (§5.3) in every vertex layout: GL_2D, GL_3D,
 * GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE. A perspective
 * projection (so clip w varies and GL_4D_COLOR_TEXTURE's w is not 1), a
 * viewport with an offset and a depth range other than [0, 1]. glPassThrough
 * markers before, between and after the points; points outside the view
 * volume (left, right, above, behind the near plane, beyond the far plane)
 * are culled and leave nothing; glVertex2f, glVertex3f and glVertex4f with
 * w != 1. The return value of glRenderMode is the number of values written.
 * Flat shading leaves points' colors alone.
 */
#include "ffl_test.h"

static void draw(void)
{
    glPassThrough(1.5f);
    glBegin(GL_POINTS);
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glTexCoord4f(0.5f, 0.25f, -1.0f, 2.0f);
    glVertex3f(0, 0, -10);            /* center */
    glColor4f(0.9f, 0.8f, 0.7f, 0.6f);
    glVertex3f(100, 0, -10);          /* right of the frustum: culled */
    glTexCoord2f(0.75f, 0.125f);
    glVertex3f(-2, 1.5f, -5);         /* inside */
    glVertex3f(0, 0, -1);             /* in front of the near plane: culled */
    glColor3f(0.3f, 0.6f, 0.9f);
    glVertex3f(1, -1, -60);           /* beyond the far plane: culled */
    glVertex2f(0.5f, -0.5f);          /* z = 0: in front of the near plane: culled */
    glVertex4f(-1, 2, -16, 2);        /* (-0.5, 1, -8) */
    glTexCoord1f(3.0f);
    glVertex3f(3, 2, -20);            /* inside */
    glVertex3f(0, 50, -10);           /* above: culled */
    glEnd();
    glPassThrough(2.5f);
    glBegin(GL_POINTS);
    glColor4f(1.0f, 0.0f, 0.5f, 1.0f);
    glVertex4f(2, -1, -30, 1);        /* inside, far */
    glEnd();
    glPassThrough(-7.0f);
}

int main(void)
{
    static const GLenum types[5] = { GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE,
                                     GL_4D_COLOR_TEXTURE };
    static const char *names[5] = { "2d", "3d", "3d_color", "3d_color_texture",
                                    "4d_color_texture" };
    GLfloat buf[256];
    GLint n;
    int t, failed = 0;

    ffl_test_init();
    glViewport(8, 4, 48, 40);
    glDepthRange(0.2, 0.9);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.75, 0.75, 2, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    for (t = 0; t < 5; t++) {
        int k;
        for (k = 0; k < 256; k++)
            buf[k] = -12345.0f;
        glFeedbackBuffer(256, types[t], buf);
        n = glRenderMode(GL_FEEDBACK);
        printf("%s enter_return %d\n", names[t], (int)n);
        draw();
        n = glRenderMode(GL_RENDER);
        printf("%s count %d\n", names[t], (int)n);
        if (n < 0 || n > 256) {
            failed = 1;
            continue;
        }
        failed |= ffl_print_feedback(names[t], buf, n, types[t]);
        printf("%s untouched_after_count %d\n", names[t], n < 256 && buf[n] == -12345.0f);
    }

    /* Flat shading changes nothing for points: each point is its own
     * provoking vertex and keeps its color. */
    glShadeModel(GL_FLAT);
    glFeedbackBuffer(256, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    n = glRenderMode(GL_RENDER);
    printf("flat count %d\n", (int)n);
    if (n >= 0 && n <= 256)
        failed |= ffl_print_feedback("flat", buf, n, GL_3D_COLOR);
    glShadeModel(GL_SMOOTH);

    /* Lighting on: GL_3D_COLOR reports the lit color. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glFeedbackBuffer(256, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    draw();
    n = glRenderMode(GL_RENDER);
    printf("lit count %d\n", (int)n);
    if (n >= 0 && n <= 256)
        failed |= ffl_print_feedback("lit", buf, n, GL_3D_COLOR);
    printf("error %s\n", ffl_error_name(glGetError()));
    return failed;
}
