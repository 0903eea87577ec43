/* ffl-test: differential */
/*
 * Display lists calling display lists (§5.4): nesting to the depth limit
 * (GL_MAX_LIST_NESTING, 64: deeper calls are ignored), a list calling itself,
 * glCallList of a list name that has no list (nothing happens), a list that
 * calls another by name (the callee's definition at execution time counts:
 * redefinition and deletion after compilation), glCallList in a
 * GL_COMPILE_AND_EXECUTE list (executed and compiled), and glCallList between
 * glBegin and glEnd (legal, §2.6.3). Each list translates the modelview matrix
 * or draws points; the matrix and the fed-back points show what ran.
 */
#include "ffl_test.h"

static GLfloat fb[4096];

static void translation(const char *what)
{
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    printf("%s translation", what);
    ffl_pf(m[12]);
    ffl_pf(m[13]);
    printf("\n");
    ffl_print_error(what);
    glLoadIdentity();
}

int main(void)
{
    GLint v = -7;
    GLint n;
    GLuint k;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGetIntegerv(GL_MAX_LIST_NESTING, &v);
    printf("max_list_nesting %d\n", (int)v);

    /* Lists 101..170: each translates by 1 and calls the next. */
    for (k = 1; k <= 70; k++) {
        glNewList(100 + k, GL_COMPILE);
        glTranslatef(1.0f, 0.0f, 0.0f);
        glCallList(101 + k);
        glEndList();
    }
    glCallList(101);
    translation("chain_from_101");
    glCallList(150);
    translation("chain_from_150");
    glNewList(200, GL_COMPILE);
    glTranslatef(0.0f, 1.0f, 0.0f);
    glCallList(101);
    glEndList();
    glCallList(200);
    translation("chain_from_200");

    /* A list that calls itself stops at the limit too. */
    glNewList(300, GL_COMPILE);
    glTranslatef(0.0f, 0.5f, 0.0f);
    glCallList(300);
    glEndList();
    glCallList(300);
    translation("self_call");

    /* Calls by name: redefinition and deletion of the callee after compilation. */
    glNewList(400, GL_COMPILE);
    glTranslatef(2.0f, 0.0f, 0.0f);
    glEndList();
    glNewList(401, GL_COMPILE);
    glCallList(400);
    glCallList(402); /* no list yet */
    glEndList();
    glCallList(401);
    translation("callee_first_definition");
    glNewList(400, GL_COMPILE);
    glTranslatef(0.0f, 3.0f, 0.0f);
    glEndList();
    glNewList(402, GL_COMPILE);
    glTranslatef(5.0f, 0.0f, 0.0f);
    glEndList();
    glCallList(401);
    translation("callee_redefined");
    glDeleteLists(400, 1);
    printf("is_list 400 %d 401 %d 402 %d\n", (int)glIsList(400), (int)glIsList(401),
           (int)glIsList(402));
    glCallList(401);
    translation("callee_deleted");
    glCallList(999);
    translation("no_such_list");

    /* glCallList in GL_COMPILE_AND_EXECUTE: executed now, compiled as a call. */
    glNewList(500, GL_COMPILE_AND_EXECUTE);
    glCallList(402);
    glEndList();
    translation("compile_and_execute_call");
    glNewList(402, GL_COMPILE);
    glTranslatef(0.0f, 7.0f, 0.0f);
    glEndList();
    glCallList(500);
    translation("compile_and_execute_call_replayed");

    /* Vertices from lists called between glBegin and glEnd, and a list that holds a
     * whole primitive called inside another list. */
    glNewList(600, GL_COMPILE);
    glColor3f(1.0f, 0.5f, 0.25f);
    glVertex2f(0.25f, 0.5f);
    glEndList();
    glNewList(601, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glCallList(600);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(0.5f, -0.25f);
    glEnd();
    glEndList();
    glFeedbackBuffer(4096, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex2f(0.0f, 0.0f);
    glCallList(600);
    glCallList(600);
    glEnd();
    glCallList(601);
    n = glRenderMode(GL_RENDER);
    ffl_print_feedback("points_and_triangle", fb, n, GL_3D_COLOR);
    ffl_print_error("points_and_triangle");
    return 0;
}
