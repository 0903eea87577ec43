/* ffl-test: differential */
/*
 * ffl-libs: -lGLU
 *
 * libGLU's NURBS renderer drawing through the GL: the same program linked with libGLU
 * against fflight and against OSMesa. GLU evaluates NURBS with the GL's evaluators
 * (glMap2f, glMapGrid2f, glEvalMesh2, glEvalCoord2f) and reads the GL's matrices and
 * viewport for its sampling. A bicubic surface and a cubic curve, lit, in every display
 * mode (GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH) and sampling method
 * (GLU_PATH_LENGTH, GLU_PARAMETRIC_ERROR, GLU_DOMAIN_DISTANCE), through feedback
 * (GL_3D_COLOR). Line segments print as "segment" whatever their token (OSMesa never feeds
 * back GL_LINE_RESET_TOKEN: difference 1 in docs/osmesa-differences.md). GLU_FILL surfaces
 * come from glEvalMesh2(GL_FILL), which OSMesa draws as triangle strips where the spec
 * has quad strips (difference 20): their feedback is compared as the number of triangles
 * and the set of distinct vertices, which any split of the same quads shares.
 */
#include <GL/glu.h>
#include "ffl_test.h"

#define BUF_SIZE 65536

static GLfloat buf[BUF_SIZE];

int main(void)
{
    static const GLenum display_modes[3] = { GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH };
    static const char *display_names[3] = { "fill", "outline_polygon", "outline_patch" };
    static const GLfloat sampling[3][3] = {
        { GLU_PATH_LENGTH, GLU_SAMPLING_TOLERANCE, 40.0f },
        { GLU_PARAMETRIC_ERROR, GLU_PARAMETRIC_TOLERANCE, 2.0f },
        { GLU_DOMAIN_DISTANCE, GLU_U_STEP, 3.0f },
    };
    static const char *sampling_names[3] = { "path_length", "parametric_error",
                                             "domain_distance" };
    static GLfloat knots[8] = { 0, 0, 0, 0, 1, 1, 1, 1 };
    static GLfloat curve_knots[8] = { 0, 0, 0, 0, 1, 1, 1, 1 };
    static const GLfloat curve_points[4][3] = {
        { -3, -2, 0 }, { -1, 3, 1 }, { 1, -3, -1 }, { 3, 2, 0 },
    };
    static const GLfloat light_position[4] = { 1, 1, 2, 0 };
    GLfloat points[4][4][3];
    GLUnurbsObj *nurbs;
    int d, s, i, j;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-5, 5, -5, 5, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glEnable(GL_NORMALIZE);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            points[i][j][0] = 2.0f * ((float)i - 1.5f);
            points[i][j][1] = 2.0f * ((float)j - 1.5f);
            points[i][j][2] = (i == 1 || i == 2) && (j == 1 || j == 2) ? 2.0f : -1.0f;
        }

    nurbs = gluNewNurbsRenderer();
    for (d = 0; d < 3; d++)
        for (s = 0; s < 3; s++) {
            char tag[64];
            GLint n;
            gluNurbsProperty(nurbs, GLU_DISPLAY_MODE, (GLfloat)display_modes[d]);
            gluNurbsProperty(nurbs, GLU_SAMPLING_METHOD, sampling[s][0]);
            gluNurbsProperty(nurbs, (GLenum)sampling[s][1], sampling[s][2]);
            if (s == 2)
                gluNurbsProperty(nurbs, GLU_V_STEP, 2.0f);
            glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, buf);
            glRenderMode(GL_FEEDBACK);
            gluBeginSurface(nurbs);
            gluNurbsSurface(nurbs, 8, knots, 8, knots, 4 * 3, 3, &points[0][0][0], 4, 4,
                            GL_MAP2_VERTEX_3);
            gluEndSurface(nurbs);
            if (d == 0) {
                n = glRenderMode(GL_RENDER);
                sprintf(tag, "%s_%s_surface", display_names[d], sampling_names[s]);
                ffl_print_vertex_set(tag, buf, n);
                glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR, buf);
                glRenderMode(GL_FEEDBACK);
            }
            gluBeginCurve(nurbs);
            gluNurbsCurve(nurbs, 8, curve_knots, 3, (GLfloat *)curve_points, 4,
                          GL_MAP1_VERTEX_3);
            gluEndCurve(nurbs);
            n = glRenderMode(GL_RENDER);
            sprintf(tag, "%s_%s", display_names[d], sampling_names[s]);
            ffl_print_feedback_segments(tag, buf, n, GL_3D_COLOR);
            ffl_print_error(tag);
        }
    gluDeleteNurbsRenderer(nurbs);
    return 0;
}
