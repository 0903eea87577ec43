/* ffl-test: differential */
/*
 * Vertex arrays in display lists (§5.4): glArrayElement, glDrawArrays,
 * glDrawElements and glDrawRangeElements compiled into a list read the arrays
 * (and the indices) at compile time. After compilation the arrays' contents,
 * pointers and enables change, and a buffer object the vertices came from is
 * rewritten: the list still draws the compiled vertices. The pointer and
 * client-state commands themselves are not compiled (they run at once).
 */
#include "ffl_test.h"

static GLfloat fb[4096];

static void draw_list(const char *what, GLuint list)
{
    GLint n;
    glFeedbackBuffer(4096, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glCallList(list);
    n = glRenderMode(GL_RENDER);
    printf("%s count %d\n", what, (int)n);
    ffl_print_feedback(what, fb, n, GL_3D_COLOR);
    ffl_print_error(what);
}

static void draw_lists(const char *what)
{
    char name[64];
    GLuint list;
    for (list = 1; list <= 5; list++) {
        snprintf(name, sizeof name, "%s_list%u", what, (unsigned)list);
        draw_list(name, list);
    }
}

int main(void)
{
    GLfloat positions[6][3] = { { -0.9f, -0.9f, 0.0f }, { 0.9f, -0.8f, 0.1f },
                                { 0.0f, 0.9f, -0.2f }, { -0.5f, 0.2f, 0.3f },
                                { 0.4f, 0.4f, 0.0f }, { 0.6f, -0.3f, 0.5f } };
    GLubyte colors[6][4] = { { 255, 0, 0, 255 }, { 0, 255, 0, 255 }, { 0, 0, 255, 255 },
                             { 255, 255, 0, 128 }, { 0, 255, 255, 64 }, { 255, 0, 255, 0 } };
    GLfloat normals[6][3] = { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 },
                              { 0, 0.6f, 0.8f }, { 0.8f, 0, 0.6f }, { 0, 0, -1 } };
    GLushort indices[6] = { 5, 3, 1, 0, 2, 4 };
    GLfloat buffer_positions[4][2] = { { -0.5f, -0.5f }, { 0.5f, -0.5f }, { 0.5f, 0.5f },
                                       { -0.5f, 0.5f } };
    static const GLfloat light[4] = { 0.3f, 0.4f, 1.0f, 0.0f };
    GLuint buffer = 0;
    int i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glNormalPointer(GL_FLOAT, 0, normals);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    /* Unlit, colors from the array; one draw per list (OSMesa loses or crashes on the
     * second vertex-array draw of a list in feedback mode). */
    glNewList(1, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEndList();
    glNewList(2, GL_COMPILE);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, indices);
    glEndList();
    glNewList(3, GL_COMPILE);
    glDrawRangeElements(GL_POINTS, 1, 5, 4, GL_UNSIGNED_SHORT, indices + 1);
    glEndList();
    glNewList(4, GL_COMPILE);
    glBegin(GL_TRIANGLE_STRIP);
    glArrayElement(4);
    glArrayElement(0);
    glArrayElement(2);
    glArrayElement(1);
    glEnd();
    glEndList();
    /* Lit, normals from the array and color material tracking the color array; the
     * client state commands inside the list run at once and are not compiled. */
    glNewList(5, GL_COMPILE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);
    glEnableClientState(GL_NORMAL_ARRAY);
    glDrawArrays(GL_TRIANGLE_FAN, 1, 5);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_LIGHTING);
    glEndList();
    printf("normal_array_after_compile %d\n", (int)glIsEnabled(GL_NORMAL_ARRAY));

    draw_lists("first");

    /* Change everything the draws read. */
    for (i = 0; i < 6; i++) {
        positions[i][0] = -positions[i][0];
        colors[i][1] = (GLubyte)(255 - colors[i][1]);
        normals[i][2] = -normals[i][2];
        indices[i] = (GLushort)(5 - indices[i]);
    }
    draw_lists("after_array_change");
    glDisableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, buffer_positions);
    draw_lists("after_pointer_change");

    /* Vertices from a buffer object, the object rewritten after compilation. */
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, sizeof buffer_positions, buffer_positions, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glNewList(6, GL_COMPILE);
    glDrawArrays(GL_QUADS, 0, 4);
    glEndList();
    for (i = 0; i < 4; i++)
        buffer_positions[i][1] *= 0.5f;
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof buffer_positions, buffer_positions);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    draw_list("buffer_after_rewrite", 6);
    glDeleteBuffers(1, &buffer);
    draw_list("buffer_after_delete", 6);

    /* Without the vertex array a draw compiles nothing to draw. */
    glDisableClientState(GL_VERTEX_ARRAY);
    glNewList(7, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndList();
    glEnableClientState(GL_VERTEX_ARRAY);
    draw_list("no_vertex_array", 7);
    return 0;
}
