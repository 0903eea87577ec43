/* ffl-test: fflight-only */
/*
 * Limits and misuse (issue 9), each with the spec's error or a documented no-op:
 * - every stack (modelview, projection, texture of each unit, color matrix, attribute,
 *   client attribute, name) pushed past its GL_MAX_*_DEPTH (GL_STACK_OVERFLOW, depth
 *   unchanged, the top intact) and popped past empty (GL_STACK_UNDERFLOW);
 * - feedback and selection overflow: glRenderMode returns -1 and nothing is written past
 *   the size given (guard values after it);
 * - glEnd without glBegin, glBegin inside glBegin, glEndList without glNewList, glNewList
 *   inside glNewList: GL_INVALID_OPERATION; glCallList nested past GL_MAX_LIST_NESTING:
 *   the deeper calls are ignored;
 * - GL calls with no context: from a thread's pthread key destructor, after fflight's
 *   per-thread state is gone. Documented (README "Contexts and threads"): no effect,
 *   queries write nothing, glGetError returns GL_NO_ERROR, fflGetCurrentContext NULL.
 * (glBegin without glEnd followed by every other command: the sweep, tests/sweep.rs, R3.)
 */
#define _POSIX_C_SOURCE 200112L
#include <pthread.h>
#include "ffl_test.h"

static int failures;
static void expect(int ok, const char *what)
{
    printf("%s %d\n", what, ok);
    failures += !ok;
}

static GLint get_int(GLenum pname)
{
    GLint v[16] = { 0 };
    glGetIntegerv(pname, v);
    return v[0];
}

/* Pushes until the depth query says full, once more (overflow), pops to empty and once
 * more (underflow). `base` is the empty depth: 1 for matrix stacks (the current matrix
 * counts), 0 for the attribute stacks. */
static void stack(const char *name, void (*push)(void), void (*pop)(void), GLenum depth, GLenum max,
                  GLint base)
{
    GLint limit = get_int(max), d, k;
    int ok = limit > 0 && get_int(depth) == base;
    char what[80];
    for (k = base; k < limit; k++)
        push();
    ok &= glGetError() == GL_NO_ERROR && get_int(depth) == limit;
    push();
    ok &= glGetError() == GL_STACK_OVERFLOW && get_int(depth) == limit;
    for (k = base; k < limit; k++)
        pop();
    d = get_int(depth);
    ok &= glGetError() == GL_NO_ERROR && d == base;
    pop();
    ok &= glGetError() == GL_STACK_UNDERFLOW && get_int(depth) == base;
    snprintf(what, sizeof what, "%s stack of %d: overflow and underflow", name, limit);
    expect(ok, what);
}

static void push_matrix(void) { glPushMatrix(); }
static void pop_matrix(void) { glPopMatrix(); }
static void push_attrib(void) { glPushAttrib(GL_ALL_ATTRIB_BITS); }
static void pop_attrib(void) { glPopAttrib(); }
static void push_client(void) { glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS); }
static void pop_client(void) { glPopClientAttrib(); }

static void matrix_stacks(void)
{
    GLint units = get_int(GL_MAX_TEXTURE_UNITS), unit;
    GLfloat top[16], after[16];
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(1.0f, 2.0f, 3.0f);
    glGetFloatv(GL_MODELVIEW_MATRIX, top);
    stack("modelview", push_matrix, pop_matrix, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH, 1);
    glGetFloatv(GL_MODELVIEW_MATRIX, after);
    expect(memcmp(top, after, sizeof top) == 0, "modelview top intact after both errors");
    glMatrixMode(GL_PROJECTION);
    stack("projection", push_matrix, pop_matrix, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, 1);
    glMatrixMode(GL_TEXTURE);
    for (unit = 0; unit < units; unit++) {
        char name[32];
        glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        snprintf(name, sizeof name, "texture unit %d", unit);
        stack(name, push_matrix, pop_matrix, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH, 1);
    }
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_COLOR);
    stack("color matrix", push_matrix, pop_matrix, GL_COLOR_MATRIX_STACK_DEPTH, GL_MAX_COLOR_MATRIX_STACK_DEPTH, 1);
    glMatrixMode(GL_MODELVIEW);
    stack("attribute", push_attrib, pop_attrib, GL_ATTRIB_STACK_DEPTH, GL_MAX_ATTRIB_STACK_DEPTH, 0);
    stack("client attribute", push_client, pop_client, GL_CLIENT_ATTRIB_STACK_DEPTH,
          GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 0);
}

static void name_stack(void)
{
    GLuint buffer[64];
    GLint limit = get_int(GL_MAX_NAME_STACK_DEPTH), k, hits;
    int ok;
    glSelectBuffer(64, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    for (k = 0; k < limit; k++)
        glPushName((GLuint)k);
    ok = glGetError() == GL_NO_ERROR && get_int(GL_NAME_STACK_DEPTH) == limit;
    glPushName(99u);
    ok &= glGetError() == GL_STACK_OVERFLOW && get_int(GL_NAME_STACK_DEPTH) == limit;
    for (k = 0; k < limit; k++)
        glPopName();
    ok &= glGetError() == GL_NO_ERROR && get_int(GL_NAME_STACK_DEPTH) == 0;
    glPopName();
    ok &= glGetError() == GL_STACK_UNDERFLOW;
    glLoadName(1u); /* on an empty stack */
    ok &= glGetError() == GL_INVALID_OPERATION;
    hits = glRenderMode(GL_RENDER);
    ok &= hits == 0;
    printf("name stack of %d: overflow, underflow, glLoadName on empty %d\n", limit, ok);
    failures += !ok;
}

static void feedback_and_selection_overflow(void)
{
    GLfloat feedback[16];
    GLuint select[16];
    GLint n, k;
    int ok = 1;
    for (k = 0; k < 16; k++) {
        feedback[k] = -7.0f;
        select[k] = 0xDEADu;
    }
    glViewport(0, 0, 64, 64);
    glLoadIdentity(); /* the modelview stack test left a translation */
    glFeedbackBuffer(8, GL_3D, feedback); /* room for two points (4 values each) */
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    for (k = 0; k < 5; k++)
        glVertex3f(0.1f * (GLfloat)k, 0.0f, 0.0f);
    glEnd();
    n = glRenderMode(GL_RENDER);
    for (k = 8; k < 16; k++)
        ok &= feedback[k] == -7.0f;
    expect(ok && n == -1 && glGetError() == GL_NO_ERROR, "feedback overflow: -1, nothing past the size");
    ok = 1;
    glSelectBuffer(6, select); /* room for one hit of three names */
    glRenderMode(GL_SELECT);
    glInitNames();
    for (k = 0; k < 4; k++) {
        glPushName((GLuint)k);
        glBegin(GL_POINTS);
        glVertex3f(0.0f, 0.0f, 0.0f);
        glEnd();
    }
    n = glRenderMode(GL_RENDER);
    for (k = 6; k < 16; k++)
        ok &= select[k] == 0xDEADu;
    expect(ok && n == -1 && glGetError() == GL_NO_ERROR, "selection overflow: -1, nothing past the size");
}

static void begin_end_and_lists(void)
{
    GLuint list = glGenLists(70), k;
    GLfloat feedback[512];
    GLint n;
    glEnd();
    expect(glGetError() == GL_INVALID_OPERATION, "glEnd without glBegin: GL_INVALID_OPERATION");
    glBegin(GL_POINTS);
    glBegin(GL_LINES);
    glEnd();
    expect(glGetError() == GL_INVALID_OPERATION, "glBegin inside glBegin: GL_INVALID_OPERATION");
    glEnd();
    expect(glGetError() == GL_INVALID_OPERATION, "the first glEnd ended it: the second is an error");
    glEndList();
    expect(glGetError() == GL_INVALID_OPERATION, "glEndList without glNewList: GL_INVALID_OPERATION");
    glNewList(list, GL_COMPILE);
    glNewList(list + 1, GL_COMPILE);
    expect(glGetError() == GL_INVALID_OPERATION, "glNewList inside glNewList: GL_INVALID_OPERATION");
    glEndList();
    /* Lists calling the next one, 70 deep: the calls past GL_MAX_LIST_NESTING are ignored. */
    for (k = 0; k < 70; k++) {
        glNewList(list + k, GL_COMPILE);
        glBegin(GL_POINTS);
        glVertex3f(0.0f, 0.0f, 0.0f);
        glEnd();
        if (k + 1 < 70)
            glCallList(list + k + 1);
        glEndList();
    }
    glFeedbackBuffer(512, GL_2D, feedback);
    glRenderMode(GL_FEEDBACK);
    glCallList(list);
    n = glRenderMode(GL_RENDER);
    printf("lists nested 70 deep: %d points fed back (GL_MAX_LIST_NESTING %d)\n", n / 3,
           get_int(GL_MAX_LIST_NESTING));
    expect(n / 3 == get_int(GL_MAX_LIST_NESTING) && glGetError() == GL_NO_ERROR,
           "calls past the nesting limit ignored");
    glDeleteLists(list, 70);
}

/* ---- no context: GL from a pthread key destructor, after the thread's state is gone ---- */
static pthread_key_t key;
static int no_context_ok = -1;

static void at_thread_exit(void *value)
{
    GLint v[4] = { -5, -5, -5, -5 };
    (void)value;
    glEnable(GL_LIGHTING);
    glBegin(GL_POINTS);
    glVertex3f(1.0f, 2.0f, 3.0f);
    glEnd();
    glGetIntegerv(GL_VIEWPORT, v);
    /* Either the thread still has its context (then GL works), or none is left and the
     * calls do nothing: both are documented; neither may crash. */
    if (v[0] == -5 && glGetError() == GL_NO_ERROR && fflGetCurrentContext() == NULL)
        no_context_ok = 1;
    else if (v[0] == 0 && glIsEnabled(GL_LIGHTING) == GL_TRUE)
        no_context_ok = 2;
    else
        no_context_ok = 0;
}

static void *thread_with_destructor(void *arg)
{
    (void)arg;
    glViewport(0, 0, 10, 10); /* this thread's default context exists */
    pthread_setspecific(key, &key);
    return NULL;
}

int main(void)
{
    pthread_t thread;
    matrix_stacks();
    name_stack();
    feedback_and_selection_overflow();
    begin_end_and_lists();
    pthread_key_create(&key, at_thread_exit);
    pthread_create(&thread, NULL, thread_with_destructor, NULL);
    pthread_join(thread, NULL);
    printf("at thread exit: %s\n", no_context_ok == 1 ? "no context, calls ignored"
                                    : no_context_ok == 2 ? "the thread's context still there" : "neither");
    expect(no_context_ok > 0, "GL calls with no context (thread exit): no effect, no crash");
    return failures;
}
