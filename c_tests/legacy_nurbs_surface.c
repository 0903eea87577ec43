/* ffl-test: differential */
/*
 * ffl-libs: -lGLU
 *
 * examples/legacy/nurbs_surface.c, a classic NURBS program (a lit bicubic NURBS surface of
 * 2 x 2 Bezier patches through GLU's NURBS renderer, GL_AUTO_NORMAL) written against the
 * system <GL/gl.h> and <GL/glu.h> only: its init(), reshape() and display() built
 * unchanged against fflight and against OSMesa, each with libGLU linked as glu_nurbs.c
 * says, display() run in feedback mode in GLU_FILL and GLU_OUTLINE_POLYGON. GLU draws the
 * filled surface with glEvalMesh2(GL_FILL), which OSMesa splits into triangle strips
 * where the spec has quad strips (docs/osmesa-differences.md, 20): that pass is compared
 * as its number of triangles and its set of distinct vertices (positions and lit colors).
 * The outline's segments are compared one for one, as "segment" whatever their token
 * (difference 1).
 */
#include <GL/gl.h>
#include "ffl_test.h"

#define main nurbs_surface_main
#include "../examples/legacy/nurbs_surface.c"
#undef main

static GLfloat buf[NURBS_FEEDBACK_SIZE];

int main(void)
{
    GLint n;
    ffl_test_init();
    init();
    reshape(64, 64);
    glFeedbackBuffer(NURBS_FEEDBACK_SIZE, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    display();
    n = glRenderMode(GL_RENDER);
    ffl_print_vertex_set("fill", buf, n);
    ffl_print_error("fill");

    gluNurbsProperty(surface, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
    glFeedbackBuffer(NURBS_FEEDBACK_SIZE, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    display();
    n = glRenderMode(GL_RENDER);
    ffl_print_feedback_segments("outline", buf, n, GL_3D_COLOR);
    ffl_print_error("outline");
    gluDeleteNurbsRenderer(surface);
    return 0;
}
