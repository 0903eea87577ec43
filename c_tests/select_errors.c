/* ffl-test: differential */
/*
 * Selection errors and state (§5.2, §6.1) where the spec and OSMesa agree: the
 * queries, glSelectBuffer with a negative size or while selecting, name-stack
 * commands outside selection mode (ignored), glLoadName on an empty stack, stack
 * overflow and underflow with no hit pending, every command between glBegin and
 * glEnd, stack errors with a hit pending (no record written). (Erroneous
 * glRenderMode calls differ: select_osmesa_diff.c.)
 */
#include "ffl_test.h"

static void get(const char *what, GLenum pname)
{
    GLint v = -7;
    glGetIntegerv(pname, &v);
    printf("%s %d\n", what, (int)v);
}

int main(void)
{
    static GLuint buf[256];
    GLint i;
    void *pointer = NULL;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    get("max_depth", GL_MAX_NAME_STACK_DEPTH);
    get("depth", GL_NAME_STACK_DEPTH);
    get("buffer_size", GL_SELECTION_BUFFER_SIZE);

    glSelectBuffer(-1, buf);
    ffl_print_error("select_buffer_negative");
    glSelectBuffer(256, buf);
    ffl_print_error("select_buffer");
    get("buffer_size", GL_SELECTION_BUFFER_SIZE);
    glGetPointerv(GL_SELECTION_BUFFER_POINTER, &pointer);
    printf("buffer_pointer %s\n", pointer == (void *)buf ? "same" : "different");

    /* Outside selection mode: ignored, even glLoadName and glPopName on an empty stack. */
    glPushName(1);
    glPushName(2);
    glLoadName(3);
    glPopName();
    glPopName();
    glPopName();
    glInitNames();
    ffl_print_error("outside_select");
    get("depth", GL_NAME_STACK_DEPTH);

    printf("enter %d\n", (int)glRenderMode(GL_SELECT));
    ffl_print_error("enter");
    get("render_mode_is_select", GL_RENDER_MODE);
    glSelectBuffer(16, buf);
    ffl_print_error("select_buffer_while_selecting");
    glSelectBuffer(-1, buf);
    ffl_print_error("select_buffer_negative_while_selecting");
    glLoadName(5);
    ffl_print_error("load_empty");
    glPopName();
    ffl_print_error("pop_empty");
    for (i = 0; i < 64; i++)
        glPushName((GLuint)i);
    ffl_print_error("push_64");
    get("depth", GL_NAME_STACK_DEPTH);
    glPushName(64);
    ffl_print_error("push_65");
    get("depth", GL_NAME_STACK_DEPTH);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glEnd();
    glLoadName(1000); /* writes the record of the 64 names, then replaces the top */
    ffl_print_error("load_full");
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0.5f);
    glEnd();
    glInitNames();
    get("depth", GL_NAME_STACK_DEPTH);

    /* Between glBegin and glEnd: GL_INVALID_OPERATION, read after glEnd. */
    glPushName(9);
    glBegin(GL_POINTS);
    glInitNames();
    glEnd();
    ffl_print_error("init_in_begin");
    glBegin(GL_POINTS);
    glPushName(1);
    glEnd();
    ffl_print_error("push_in_begin");
    glBegin(GL_POINTS);
    glPopName();
    glEnd();
    ffl_print_error("pop_in_begin");
    glBegin(GL_POINTS);
    glLoadName(1);
    glEnd();
    ffl_print_error("load_in_begin");
    glBegin(GL_POINTS);
    glSelectBuffer(4, buf);
    glEnd();
    ffl_print_error("select_buffer_in_begin");
    glBegin(GL_POINTS);
    glRenderMode(GL_RENDER);
    glEnd();
    ffl_print_error("render_mode_in_begin");
    get("depth", GL_NAME_STACK_DEPTH);
    get("render_mode_is_select", GL_RENDER_MODE);

    i = glRenderMode(GL_RENDER);
    ffl_print_hits("select", buf, i, 256);

    /* Stack errors with a hit pending write no record (§2.5): two records, not three. */
    glRenderMode(GL_SELECT);
    for (i = 0; i < 64; i++)
        glPushName((GLuint)i);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glEnd();
    glPushName(64);
    ffl_print_error("push_full_hit_pending");
    glInitNames();
    glBegin(GL_POINTS);
    glVertex3f(0, 0, -0.5f);
    glEnd();
    glPopName();
    ffl_print_error("pop_empty_hit_pending");
    i = glRenderMode(GL_RENDER);
    ffl_print_hits("pending", buf, i, 256);
    ffl_print_error("leave");
    get("depth", GL_NAME_STACK_DEPTH);
    return 0;
}
