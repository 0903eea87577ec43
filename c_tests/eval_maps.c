/* ffl-test: differential */
/*
 * Evaluators (§5.1) through feedback and queries: a cubic curve (GL_MAP1_VERTEX_3 with a
 * color map) by glEvalMesh1 in GL_POINT and GL_LINE and by glEvalCoord1/glEvalPoint1; a
 * bicubic patch (GL_MAP2_VERTEX_3) lit with GL_AUTO_NORMAL by glEvalMesh2 in GL_LINE and
 * GL_POINT (GL_FILL: eval_osmesa_diff_mesh_fill.c); a rational patch (GL_MAP2_VERTEX_4) with a normal map and a
 * texture coordinate map by glEvalCoord2 between glBegin and glEnd (the current color
 * unchanged after); the same patch from a display list;
 * glGetMap (GL_COEFF, GL_ORDER, GL_DOMAIN), the grid queries and GL_MAX_EVAL_ORDER; the
 * errors of bad targets, orders, strides, domains, grids, mesh modes, units and glBegin.
 */
#include "ffl_test.h"

#define BUF_SIZE 8192

static GLfloat buf[BUF_SIZE];

static const GLfloat curve[4][3] = {
    { -4, -4, 0 }, { -2, 4, 0.5f }, { 2, -4, -0.5f }, { 4, 4, 0 },
};
static const GLfloat curve_colors[2][4] = { { 1, 0, 0, 1 }, { 0, 0.5f, 1, 0.5f } };
static GLfloat patch[4][4][3];
static GLfloat rational[3][2][4];
static const GLfloat normals[2][2][3] = {
    { { 0, 0, 1 }, { 0, 1, 1 } }, { { 1, 0, 1 }, { 1, 1, 0 } },
};
static const GLfloat tex[2][2][2] = { { { 0, 0 }, { 0, 1 } }, { { 1, 0 }, { 1, 1 } } };

static void print_map(const char *what, GLenum target, int coefficients)
{
    GLfloat values[256];
    GLdouble domain[4];
    GLint order[2] = { -1, -1 };
    glGetMapiv(target, GL_ORDER, order);
    printf("%s order %d %d\n", what, (int)order[0], (int)order[1]);
    glGetMapdv(target, GL_DOMAIN, domain);
    printf("%s", what);
    ffl_pdv("domain", domain, target >= GL_MAP2_COLOR_4 ? 4 : 2);
    printf("\n");
    glGetMapfv(target, GL_COEFF, values);
    printf("%s", what);
    ffl_pfv("coeff", values, coefficients);
    printf("\n");
}

static void start(GLenum type)
{
    glFeedbackBuffer(BUF_SIZE, type, buf);
    glRenderMode(GL_FEEDBACK);
}

static void finish(const char *tag, GLenum type)
{
    GLint n = glRenderMode(GL_RENDER);
    printf("%s count %d\n", tag, (int)n);
    ffl_print_feedback(tag, buf, n, type);
    ffl_print_error(tag);
}

/* A pass of line strips: each segment printed as "segment" whatever its token, then how
 * many were GL_LINE_RESET_TOKEN against the spec's count, one a strip (§5.3: the stipple
 * restarts with each strip; OSMesa feeds back GL_LINE_TOKEN throughout, difference 1 in
 * docs/osmesa-differences.md). */
static void finish_lines(const char *tag, int strips)
{
    GLint n = glRenderMode(GL_RENDER), i = 0;
    int resets = 0;
    printf("%s count %d\n", tag, (int)n);
    while (i + 1 + 2 * 3 <= n) {
        GLenum token = (GLenum)buf[i];
        if (token != GL_LINE_TOKEN && token != GL_LINE_RESET_TOKEN)
            break;
        resets += token == GL_LINE_RESET_TOKEN;
        printf("%s segment\n%s  v", tag, tag);
        ffl_print_feedback_vertex(buf + i + 1, GL_3D);
        printf("\n%s  v", tag);
        ffl_print_feedback_vertex(buf + i + 4, GL_3D);
        printf("\n");
        i += 7;
    }
    printf("%s parsed %d\n", tag, i == n);
    printf("%s resets count %d ref count %d osmesa-exempt=line_reset\n", tag, resets, strips);
    ffl_print_error(tag);
}

static void curves(void)
{
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glMap1f(GL_MAP1_COLOR_4, 0.0f, 1.0f, 4, 2, &curve_colors[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glEnable(GL_MAP1_COLOR_4);
    glMapGrid1f(8, 0.0f, 1.0f);
    start(GL_3D_COLOR);
    glEvalMesh1(GL_POINT, 0, 8);
    glBegin(GL_POINTS);
    glEvalCoord1f(0.125f);
    glEvalPoint1(3);
    glEvalCoord1d(0.9);
    glEnd();
    finish("curve", GL_3D_COLOR);
    start(GL_3D);
    glEvalMesh1(GL_LINE, 2, 6);
    glBegin(GL_LINE_STRIP);
    glEvalCoord1f(0.125f);
    glEvalPoint1(3);
    glEvalCoord1d(0.9);
    glEnd();
    finish_lines("curve_lines", 2);
    /* A reversed domain, a grid beyond it. */
    {
        GLdouble d[4][3];
        int i, k;
        for (i = 0; i < 4; i++)
            for (k = 0; k < 3; k++)
                d[i][k] = curve[i][k];
        glMap1d(GL_MAP1_VERTEX_3, 2.0, -1.0, 3, 4, &d[0][0]);
    }
    glMapGrid1d(4, -1.0, 3.0);
    start(GL_3D_COLOR);
    glEvalMesh1(GL_POINT, 0, 4);
    finish("curve_reversed", GL_3D_COLOR);
    print_map("map1_vertex_3", GL_MAP1_VERTEX_3, 12);
    print_map("map1_color_4", GL_MAP1_COLOR_4, 8);
    glDisable(GL_MAP1_VERTEX_3);
    glDisable(GL_MAP1_COLOR_4);
}

static void lit_patch(void)
{
    static const GLfloat light_position[4] = { 1, 2, 3, 0 };
    static const GLfloat diffuse[4] = { 0.8f, 0.6f, 0.4f, 1 };
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            patch[i][j][0] = -3.0f + 2.0f * (float)i;
            patch[i][j][1] = -3.0f + 2.0f * (float)j;
            patch[i][j][2] = (i == 1 || i == 2) && (j == 1 || j == 2) ? 2.0f : 0.0f;
        }
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(4, 0.0f, 1.0f, 3, 0.0f, 1.0f);
    start(GL_3D_COLOR);
    glEvalMesh2(GL_POINT, 0, 4, 0, 3);
    finish("patch_points", GL_3D_COLOR);
    start(GL_3D);
    glEvalMesh2(GL_LINE, 1, 3, 0, 2);
    finish_lines("patch_lines", 3 + 3);
    print_map("map2_vertex_3", GL_MAP2_VERTEX_3, 48);
}

static void rational_patch(void)
{
    GLuint list;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 2; j++) {
            GLfloat w = 1.0f + 0.5f * (float)(i * j);
            rational[i][j][0] = (-2.0f + 2.0f * (float)i) * w;
            rational[i][j][1] = (-2.0f + 4.0f * (float)j) * w;
            rational[i][j][2] = (i == 1 ? 1.5f : 0.0f) * w;
            rational[i][j][3] = w;
        }
    glDisable(GL_MAP2_VERTEX_3);
    glMap2f(GL_MAP2_VERTEX_4, 0, 2, 8, 3, 0, 1, 4, 2, &rational[0][0][0]);
    glMap2f(GL_MAP2_NORMAL, 0, 1, 6, 2, 0, 1, 3, 2, &normals[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 4, 2, 0, 1, 2, 2, &tex[0][0][0]);
    glEnable(GL_MAP2_VERTEX_4);
    glEnable(GL_MAP2_NORMAL);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glDisable(GL_AUTO_NORMAL);
    glColor4f(0.2f, 0.4f, 0.6f, 0.8f);
    glNormal3f(0.0f, 0.0f, -1.0f);
    glTexCoord4f(0.1f, 0.2f, 0.3f, 0.4f);
    start(GL_4D_COLOR_TEXTURE);
    glBegin(GL_TRIANGLES);
    glEvalCoord2f(0.0f, 0.0f);
    glEvalCoord2f(1.5f, 0.25f);
    glEvalCoord2d(0.5, 1.0);
    glEnd();
    finish("rational", GL_4D_COLOR_TEXTURE);
    /* (The current normal and texture coordinates after evaluation:
     * eval_osmesa_diff_mesh_fill.c.) */
    ffl_print_floats("current color", GL_CURRENT_COLOR, 4);

    /* Automatic normals of the rational patch, compiled into a list. */
    glEnable(GL_AUTO_NORMAL);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glMapGrid2f(2, 0.0f, 2.0f, 2, 0.0f, 1.0f);
    glEvalMesh2(GL_POINT, 0, 2, 0, 2);
    glEndList();
    glMapGrid2f(1, 0.0f, 1.0f, 1, 0.0f, 1.0f);
    start(GL_3D_COLOR);
    glCallList(list);
    finish("rational_list", GL_3D_COLOR);
    ffl_print_floats("grid2 domain", GL_MAP2_GRID_DOMAIN, 4);
    ffl_print_ints("grid2 segments", GL_MAP2_GRID_SEGMENTS, 2);
    glDeleteLists(list, 1);
}

/* A curve of the largest order GL_MAX_EVAL_ORDER allows here (30, as Mesa's). */
static void highest_order(void)
{
    static GLfloat points[30][3];
    ffl_rng rng;
    GLint max_order = 0;
    int k;
    glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
    if (max_order > 30)
        max_order = 30;
    ffl_rng_seed(&rng, 30);
    for (k = 0; k < max_order; k++) {
        points[k][0] = -4.0f + 8.0f * (float)k / (float)(max_order - 1);
        points[k][1] = ffl_rng_float(&rng, -3.0, 3.0);
        points[k][2] = ffl_rng_float(&rng, -1.0, 1.0);
    }
    glDisable(GL_LIGHTING);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, max_order, &points[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(10, 0.0f, 1.0f);
    start(GL_3D);
    glEvalMesh1(GL_POINT, 0, 10);
    finish("order_30", GL_3D);
    glDisable(GL_MAP1_VERTEX_3);
    glEnable(GL_LIGHTING);
}

static void errors(void)
{
    GLfloat values[4];
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, &curve[0][0]);
    ffl_print_error("order 0");
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, &curve[0][0]);
    ffl_print_error("order 31");
    glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 4, &curve[0][0]);
    ffl_print_error("u1 == u2");
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 2, 4, &curve[0][0]);
    ffl_print_error("stride < k");
    glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    ffl_print_error("map1 of a map2 target");
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 0, 12, 4, &patch[0][0][0]);
    ffl_print_error("v1 == v2");
    glMapGrid1f(0, 0, 1);
    ffl_print_error("grid1 0");
    glMapGrid2f(2, 0, 1, -1, 0, 1);
    ffl_print_error("grid2 -1");
    glEvalMesh1(GL_FILL, 0, 1);
    ffl_print_error("mesh1 fill");
    glEvalMesh2(GL_LINE_STRIP, 0, 1, 0, 1);
    ffl_print_error("mesh2 bad mode");
    glGetMapfv(GL_MAP2_VERTEX_3, GL_AMBIENT, values);
    ffl_print_error("get bad query");
    glGetMapfv(GL_LIGHT0, GL_ORDER, values);
    ffl_print_error("get bad target");
    glActiveTexture(GL_TEXTURE1);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    ffl_print_error("map on unit 1");
    glActiveTexture(GL_TEXTURE0);
    glBegin(GL_POINTS);
    glEvalMesh1(GL_POINT, 0, 1);
    glEnd();
    ffl_print_error("mesh in begin/end");
    glBegin(GL_POINTS);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    glEnd();
    ffl_print_error("map in begin/end");
    /* Negative and empty meshes draw nothing. */
    start(GL_3D);
    glEvalMesh2(GL_FILL, 2, 1, 0, 1);
    glEvalMesh1(GL_LINE, 3, 3);
    finish("empty meshes", GL_3D);
    print_map("after errors", GL_MAP1_VERTEX_3, 12);
}

int main(void)
{
    GLint max_order = 0;
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-6, 6, -6, 6, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(20.0f, 1.0f, 0.5f, 0.0f);

    glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
    printf("max eval order at least 8: %d\n", max_order >= 8);
    print_map("initial map1_vertex_4", GL_MAP1_VERTEX_4, 4);
    print_map("initial map2_normal", GL_MAP2_NORMAL, 3);
    print_map("initial map1_color_4", GL_MAP1_COLOR_4, 4);
    print_map("initial map2_texture_coord_3", GL_MAP2_TEXTURE_COORD_3, 3);
    ffl_print_floats("initial grid1 domain", GL_MAP1_GRID_DOMAIN, 2);
    ffl_print_ints("initial grid1 segments", GL_MAP1_GRID_SEGMENTS, 1);
    ffl_print_bools("initial map2_vertex_3", GL_MAP2_VERTEX_3, 1, 1);
    curves();
    lit_patch();
    rational_patch();
    highest_order();
    errors();
    return 0;
}
