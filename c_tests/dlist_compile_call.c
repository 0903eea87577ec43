/* ffl-test: differential */
/*
 * Display lists (§5.4) holding a lit scene: lights, a material, enables,
 * matrices, color material, and glBegin/glEnd geometry with glMaterial and
 * glColor between the vertices. The same commands are fed back immediately,
 * from a GL_COMPILE list called twice (the second call after the state the
 * list sets was changed back), and from a GL_COMPILE_AND_EXECUTE list (which
 * draws while it compiles). Compiling in GL_COMPILE mode draws nothing and
 * changes no state: the feedback count and glIsEnabled say so.
 */
#include "ffl_test.h"

static GLfloat fb[4096];

static void scene(void)
{
    static const GLfloat position[4] = { 1.0f, 2.0f, 3.0f, 0.0f };
    static const GLfloat diffuse[4] = { 0.8f, 0.3f, 0.2f, 1.0f };
    static const GLfloat specular[4] = { 0.5f, 0.5f, 0.5f, 1.0f };
    static const GLfloat spot_position[4] = { 0.0f, 0.0f, 2.0f, 1.0f };
    static const GLfloat matrix[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.1f, -0.2f, 0, 1 };
    static const GLfloat shiny[4] = { 0.9f, 0.9f, 0.1f, 1.0f };
    static const GLfloat vertex[3] = { 0.2f, 0.6f, -0.1f };

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2, 2, -2, 2, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadMatrixf(matrix);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(1.1f, 0.9f, 1.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_POSITION, position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
    glLightfv(GL_LIGHT1, GL_POSITION, spot_position);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 60.0f);
    glLighti(GL_LIGHT1, GL_SPOT_EXPONENT, 2);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glShadeModel(GL_SMOOTH);

    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-1.0f, -1.0f, 0.0f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, shiny);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glNormal3f(0.0f, 0.6f, 0.8f);
    glVertex3fv(vertex);
    glEnd();

    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(-1.5f, -1.5f);
    glColor4ub(0, 255, 0, 128);
    glVertex2f(-0.5f, -1.5f);
    glColor3d(0.0, 0.0, 1.0);
    glVertex2i(0, 0);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(-1.5f, -0.5f);
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    glPopMatrix();
}

/* The state the scene changes, set back to GL's initial values. */
static void reset(void)
{
    static const GLfloat white[4] = { 1, 1, 1, 1 };
    static const GLfloat zero[4] = { 0, 0, 0, 1 };
    static const GLfloat ambient[4] = { 0.2f, 0.2f, 0.2f, 1.0f };
    static const GLfloat diffuse[4] = { 0.8f, 0.8f, 0.8f, 1.0f };
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0f);
    glColor4f(1, 1, 1, 1);
}

static void feedback(const char *what, void (*draw)(GLuint), GLuint list)
{
    GLint n;
    glFeedbackBuffer(4096, GL_3D_COLOR, fb);
    glRenderMode(GL_FEEDBACK);
    draw(list);
    n = glRenderMode(GL_RENDER);
    printf("%s count %d\n", what, (int)n);
    ffl_print_feedback(what, fb, n, GL_3D_COLOR);
    ffl_print_error(what);
}

static void immediate(GLuint list)
{
    (void)list;
    scene();
}

static void call(GLuint list)
{
    glCallList(list);
}

static void compile_and_execute(GLuint list)
{
    glNewList(list, GL_COMPILE_AND_EXECUTE);
    scene();
    glEndList();
}

static void compile(GLuint list)
{
    glNewList(list, GL_COMPILE);
    scene();
    glEndList();
}

int main(void)
{
    ffl_test_init();
    glViewport(0, 0, 64, 64);

    feedback("immediate", immediate, 0);
    reset();

    feedback("compile", compile, 1);
    printf("after_compile lighting %d light0 %d\n", (int)glIsEnabled(GL_LIGHTING),
           (int)glIsEnabled(GL_LIGHT0));
    ffl_print_floats("after_compile matrix", GL_MODELVIEW_MATRIX, 16);
    feedback("call", call, 1);
    reset();
    feedback("call_again", call, 1);
    reset();

    feedback("compile_and_execute", compile_and_execute, 2);
    reset();
    feedback("call_compiled_and_executed", call, 2);
    printf("after_call lighting %d light0 %d\n", (int)glIsEnabled(GL_LIGHTING),
           (int)glIsEnabled(GL_LIGHT0));
    return 0;
}
