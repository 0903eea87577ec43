/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: drawing from a mapped buffer object.
 *
 * GL 1.5 §2.9.1: "Attempts to source data from a currently mapped buffer
 * object will generate an INVALID_OPERATION error." OSMesa (Mesa 22.3, a
 * compatibility context) draws from the mapped store without an error.
 * fflight follows the spec: GL_INVALID_OPERATION and nothing drawn, for
 * glDrawArrays with a mapped vertex array buffer and for glDrawElements with
 * a mapped element array buffer.
 */
#include "ffl_test.h"

int main(void)
{
    static const GLfloat points[3 * 3] = { 0, 0, -0.5f, 0.5f, 0, -0.5f, 0, 0.5f, -0.5f };
    static const GLubyte indices[3] = { 0, 1, 2 };
    GLuint buffers[2];
    GLfloat feedback[256];
    GLint values;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGenBuffers(2, buffers);
    glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof points, points, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, (const void *)0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glFeedbackBuffer(256, GL_3D, feedback);

    glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    glRenderMode(GL_FEEDBACK);
    glDrawArrays(GL_POINTS, 0, 3);
    printf("draw_arrays_mapped error_code %d ref error_code %d\n", (int)glGetError(),
           GL_INVALID_OPERATION);
    values = glRenderMode(GL_RENDER);
    printf("draw_arrays_mapped fed_back values %d ref values 0\n", (int)values);
    glUnmapBuffer(GL_ARRAY_BUFFER);

    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
    glMapBuffer(GL_ELEMENT_ARRAY_BUFFER, GL_READ_ONLY);
    glRenderMode(GL_FEEDBACK);
    glDrawElements(GL_POINTS, 3, GL_UNSIGNED_BYTE, (const void *)0);
    printf("draw_elements_mapped error_code %d ref error_code %d\n", (int)glGetError(),
           GL_INVALID_OPERATION);
    values = glRenderMode(GL_RENDER);
    printf("draw_elements_mapped fed_back values %d ref values 0\n", (int)values);
    return 0;
}
