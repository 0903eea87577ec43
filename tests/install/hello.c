/* Built against an installed fflight with `pkg-config --cflags --libs fflight` (make
 * test-install): lights one vertex and checks its fed-back color. */
#include <fflight.h>
#include <math.h>
#include <stdio.h>

int main(void)
{
    static const GLfloat position[4] = { 0.0f, 0.0f, 1.0f, 0.0f };
    GLfloat feedback[8];
    GLint n;
    glViewport(0, 0, 100, 100);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glFeedbackBuffer(8, GL_3D_COLOR, feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.0f, 0.0f, 0.0f);
    glEnd();
    n = glRenderMode(GL_RENDER);
    /* Default material and light: 0.2 * 0.2 ambient + 0.8 diffuse = 0.84. */
    if (n != 8 || fabs(feedback[4] - 0.84) > 1e-6) {
        printf("unexpected feedback (%d values, red %g)\n", (int)n, (double)feedback[4]);
        return 1;
    }
    printf("fflight from pkg-config: red %g\n", (double)feedback[4]);
    return 0;
}
