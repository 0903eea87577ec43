// Built against an installed fflight with CMake's find_package(fflight) (make test-install).
#include <fflight.h>

#include <cmath>
#include <cstdio>

int main()
{
    const GLfloat position[4] = {0.0f, 0.0f, 1.0f, 0.0f};
    GLfloat feedback[8];
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
    const GLint n = glRenderMode(GL_RENDER);
    if (n != 8 || std::fabs(feedback[4] - 0.84) > 1e-6) {
        std::printf("unexpected feedback (%d values)\n", static_cast<int>(n));
        return 1;
    }
    std::printf("fflight from CMake: red %g\n", static_cast<double>(feedback[4]));
    return 0;
}
