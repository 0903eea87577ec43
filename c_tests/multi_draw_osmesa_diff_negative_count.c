/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: a negative count in glMultiDrawArrays' list.
 *
 * GL 1.5 §2.8 defines glMultiDrawArrays as the loop
 *     for (i = 0; i < primcount; i++) if (count[i] > 0) DrawArrays(mode, first[i], count[i]);
 * so a negative count[i] is skipped like 0 and the other draws happen, with
 * no error. OSMesa checks every count first and rejects the whole call with
 * GL_INVALID_VALUE (later GL versions made that the rule). The same holds for
 * glMultiDrawElements.
 *
 * Here: three points in two draws around a count of -1, into GL_3D feedback.
 */
#include "ffl_test.h"

int main(void)
{
    static const GLfloat points[3 * 3] = { 0, 0, 0, 0.5f, 0, 0, 0, 0.5f, 0 };
    static const GLubyte indices[3] = { 0, 1, 2 };
    static const GLint firsts[3] = { 0, 0, 1 };
    static const GLsizei counts[3] = { 1, -1, 2 };
    const GLvoid *lists[3];
    GLfloat feedback[256];
    GLint values;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glVertexPointer(3, GL_FLOAT, 0, points);
    glEnableClientState(GL_VERTEX_ARRAY);
    glFeedbackBuffer(256, GL_3D, feedback);

    glRenderMode(GL_FEEDBACK);
    glMultiDrawArrays(GL_POINTS, firsts, counts, 3);
    printf("arrays error_code %d ref error_code 0\n", (int)glGetError());
    values = glRenderMode(GL_RENDER);
    printf("arrays fed_back values %d ref values 12\n", (int)values);

    lists[0] = indices;
    lists[1] = indices;
    lists[2] = indices + 1;
    glRenderMode(GL_FEEDBACK);
    glMultiDrawElements(GL_POINTS, counts, GL_UNSIGNED_BYTE, lists, 3);
    printf("elements error_code %d ref error_code 0\n", (int)glGetError());
    values = glRenderMode(GL_RENDER);
    printf("elements fed_back values %d ref values 12\n", (int)values);
    return 0;
}
