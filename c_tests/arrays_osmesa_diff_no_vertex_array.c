/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: drawing with the vertex array disabled.
 *
 * GL 1.5 §2.8 defines glDrawArrays and glDrawElements through glArrayElement,
 * which calls glVertex only "if VERTEX_ARRAY is enabled": without the vertex
 * array no vertex is specified and nothing is drawn (the other enabled
 * arrays only set current attributes). OSMesa, like later GL versions'
 * generic attribute 0, draws every element at the current raster position
 * instead: here 4 points and 2 triangles at the origin.
 *
 * Here: a color array enabled, the vertex array not; glDrawArrays(GL_POINTS)
 * and glDrawElements(GL_TRIANGLES) into feedback. fflight feeds back only the
 * two glPassThrough markers (4 values).
 */
#include "ffl_test.h"

int main(void)
{
    static const GLfloat colors[6 * 4] = { 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1,
                                           1, 1, 0, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
    static const GLubyte indices[6] = { 0, 1, 2, 3, 4, 5 };
    GLfloat buf[256];
    GLint n;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glColorPointer(4, GL_FLOAT, 0, colors);
    glEnableClientState(GL_COLOR_ARRAY);
    glFeedbackBuffer(256, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glPassThrough(1);
    glDrawArrays(GL_POINTS, 0, 4);
    glPassThrough(2);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, indices);
    n = glRenderMode(GL_RENDER);
    printf("fed_back values %d ref values 4\n", (int)n);
    printf("error %s\n", ffl_error_name(glGetError()));
    return 0;
}
