/* ffl-test: differential */
/*
 * glMultiDrawArrays and glMultiDrawElements (GL 1.4, §2.8): the same
 * feedback as the glDrawArrays / glDrawElements calls of the spec's loop, for
 * strips and fans whose primitives restart with each draw (line strips are
 * left out: the printer's model of line stipple resets knows one glBegin per
 * marker), with indices in client
 * memory and in an element array buffer (offsets); counts of 0 are skipped;
 * primcount 0 draws nothing; the call's errors (negative primcount, bad mode,
 * bad index type, inside glBegin/glEnd). (Negative counts in the list:
 * buffer-free, see multi_draw_osmesa_diff_negative_count.c.)
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"

#define FEEDBACK 4096

static GLfloat feedback[FEEDBACK];
static ffl_fb fb;

static void start(GLenum mode)
{
    ffl_fb_draw_start(&fb, feedback, FEEDBACK, GL_3D_COLOR, mode);
}

static int finish(const char *label)
{
    return ffl_fb_draw_finish(&fb, label);
}

int main(void)
{
    static GLfloat positions[12][3];
    static GLfloat colors[12][4];
    static const GLint firsts[4] = { 0, 5, 2, 7 };
    static const GLsizei counts[4] = { 4, 0, 3, 5 };
    static const GLushort list_a[5] = { 0, 2, 1, 3, 4 };
    static const GLushort list_b[4] = { 11, 9, 10, 8 };
    static const GLushort all[9] = { 0, 2, 1, 3, 4, 11, 9, 10, 8 };
    const GLvoid *lists[2];
    const GLvoid *offsets[2];
    GLsizei list_counts[2] = { 5, 4 };
    GLuint buffer;
    int failed = 0, i;

    ffl_test_init();
    for (i = 0; i < 12; i++) {
        positions[i][0] = (GLfloat)(i % 4) * 0.4f - 0.6f;
        positions[i][1] = (GLfloat)(i / 4) * 0.5f - 0.5f;
        positions[i][2] = (GLfloat)(i % 3) * 0.1f;
        colors[i][0] = (GLfloat)i / 12.0f;
        colors[i][1] = 1.0f - (GLfloat)i / 12.0f;
        colors[i][2] = 0.5f;
        colors[i][3] = 1.0f;
    }
    glViewport(0, 0, 64, 64);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glColorPointer(4, GL_FLOAT, 0, colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    start(GL_LINES);
    glMultiDrawArrays(GL_LINES, firsts, counts, 4);
    failed |= finish("multi_arrays_lines");
    start(GL_TRIANGLE_STRIP);
    glMultiDrawArrays(GL_TRIANGLE_STRIP, firsts, counts, 4);
    failed |= finish("multi_arrays_triangle_strip");
    start(GL_POINTS);
    glMultiDrawArrays(GL_POINTS, NULL, NULL, 0);
    failed |= finish("multi_arrays_none");

    lists[0] = list_a;
    lists[1] = list_b;
    start(GL_TRIANGLE_STRIP);
    glMultiDrawElements(GL_TRIANGLE_STRIP, list_counts, GL_UNSIGNED_SHORT, lists, 2);
    failed |= finish("multi_elements_triangle_strip");

    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof all, all, GL_STATIC_DRAW);
    offsets[0] = (const GLvoid *)0;
    offsets[1] = (const GLvoid *)(5 * sizeof(GLushort));
    start(GL_TRIANGLE_FAN);
    glMultiDrawElements(GL_TRIANGLE_FAN, list_counts, GL_UNSIGNED_SHORT, offsets, 2);
    failed |= finish("multi_elements_buffer_fan");
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

    glMultiDrawArrays(GL_POINTS, firsts, counts, -1);
    printf("arrays_negative_primcount error %s\n", ffl_error_name(glGetError()));
    glMultiDrawArrays(0x77, firsts, counts, 1);
    printf("arrays_bad_mode error %s\n", ffl_error_name(glGetError()));
    glMultiDrawElements(GL_POINTS, list_counts, GL_UNSIGNED_SHORT, lists, -1);
    printf("elements_negative_primcount error %s\n", ffl_error_name(glGetError()));
    glMultiDrawElements(GL_POINTS, list_counts, GL_FLOAT, lists, 2);
    printf("elements_bad_type error %s\n", ffl_error_name(glGetError()));
    glMultiDrawElements(0x77, list_counts, GL_UNSIGNED_SHORT, lists, 2);
    printf("elements_bad_mode error %s\n", ffl_error_name(glGetError()));
    glBegin(GL_POINTS);
    glMultiDrawArrays(GL_POINTS, firsts, counts, 1);
    glEnd();
    printf("inside_begin_end error %s\n", ffl_error_name(glGetError()));
    return failed;
}
