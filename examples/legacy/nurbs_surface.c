/*
 * A classic NURBS program in the style of the Red Book's surface.c: a lit bicubic NURBS
 * surface (a 5 x 5 control net over the knots 0 0 0 0 0.5 1 1 1 1 in each direction, so
 * 2 x 2 Bezier patches: a hill with a dip) drawn through GLU's NURBS renderer with
 * GL_AUTO_NORMAL, filled (GLU_FILL) and as its tessellation's outline
 * (GLU_OUTLINE_POLYGON), in feedback mode. Written against the system <GL/gl.h> and
 * <GL/glu.h> only, as init(), reshape() and display(); it runs unchanged against fflight
 * and against OSMesa (with -DFFL_OSMESA, which only adds a context), with libGLU drawing
 * through whichever GL the program is linked with. c_tests/legacy_nurbs_surface.c
 * compares the two.
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include "legacy_feedback.h"

#define NURBS_FEEDBACK_SIZE 65536

static GLfloat control_points[5][5][3];
static GLfloat knots[9] = { 0.0f, 0.0f, 0.0f, 0.0f, 0.5f, 1.0f, 1.0f, 1.0f, 1.0f };
static GLUnurbsObj *surface;

static void init_surface(void)
{
    int u, v;
    for (u = 0; u < 5; u++)
        for (v = 0; v < 5; v++) {
            control_points[u][v][0] = 1.5f * ((GLfloat)u - 2.0f);
            control_points[u][v][1] = 1.5f * ((GLfloat)v - 2.0f);
            if ((u == 1 || u == 2) && (v == 1 || v == 2))
                control_points[u][v][2] = 2.5f;
            else if (u == 3 && v == 3)
                control_points[u][v][2] = -2.0f;
            else
                control_points[u][v][2] = -0.5f;
        }
}

static void init(void)
{
    static const GLfloat diffuse[4] = { 0.7f, 0.6f, 0.4f, 1.0f };
    static const GLfloat specular[4] = { 0.8f, 0.8f, 0.8f, 1.0f };
    static const GLfloat light_position[4] = { 1.0f, 2.0f, 3.0f, 0.0f };

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);

    init_surface();
    surface = gluNewNurbsRenderer();
    gluNurbsProperty(surface, GLU_SAMPLING_TOLERANCE, 25.0f);
    gluNurbsProperty(surface, GLU_DISPLAY_MODE, GLU_FILL);
}

static void reshape(int width, int height)
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-5.0, 5.0, -5.0, 5.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(330.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.8f, 0.8f, 0.8f);
    gluBeginSurface(surface);
    gluNurbsSurface(surface, 9, knots, 9, knots, 5 * 3, 3, &control_points[0][0][0], 4, 4,
                    GL_MAP2_VERTEX_3);
    gluEndSurface(surface);
    glPopMatrix();
    glFlush();
}

static GLfloat nurbs_feedback[NURBS_FEEDBACK_SIZE];

int main(void)
{
    if (legacy_make_current() != 0)
        return 1;
    init();
    reshape(64, 64);
    glFeedbackBuffer(NURBS_FEEDBACK_SIZE, GL_3D_COLOR, nurbs_feedback);
    glRenderMode(GL_FEEDBACK);
    display();
    legacy_print_feedback("fill", nurbs_feedback, glRenderMode(GL_RENDER), GL_3D_COLOR);

    gluNurbsProperty(surface, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
    glFeedbackBuffer(NURBS_FEEDBACK_SIZE, GL_3D_COLOR, nurbs_feedback);
    glRenderMode(GL_FEEDBACK);
    display();
    legacy_print_feedback("outline", nurbs_feedback, glRenderMode(GL_RENDER), GL_3D_COLOR);
    printf("nurbs error %d\n", (int)glGetError());
    gluDeleteNurbsRenderer(surface);
    return 0;
}
