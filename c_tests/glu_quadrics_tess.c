/* ffl-test: differential */
/*
 * ffl-libs: -lGLU
 *
 * libGLU's quadrics and polygon tessellator drawing through the GL: the same program
 * linked with libGLU against fflight and against OSMesa, through feedback
 * (GL_3D_COLOR_TEXTURE), lit. Quadrics: gluSphere, gluCylinder, gluDisk and
 * gluPartialDisk in every draw style (GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT),
 * normals mode (GLU_NONE, GLU_FLAT, GLU_SMOOTH; GLU_FLAT points and silhouettes of
 * the disks only, see quadrics()) and orientation, with gluQuadricTexture on and off. Tessellator: a concave polygon with a
 * hole under every winding rule, with the edge flag callback (the flags it passes printed,
 * then given to glEdgeFlag), and a self-intersecting star through the combine callback. Segments print
 * as "segment" whatever their token (difference 1 in docs/osmesa-differences.md).
 */
#include <GL/glu.h>
#include "ffl_test.h"

#define BUF_SIZE 65536

static GLfloat buf[BUF_SIZE];

static void start(GLfloat *buffer)
{
    glFeedbackBuffer(BUF_SIZE, GL_3D_COLOR_TEXTURE, buffer);
    glRenderMode(GL_FEEDBACK);
}

static void finish(const char *tag)
{
    GLint n = glRenderMode(GL_RENDER);
    ffl_print_feedback_segments(tag, buf, n, GL_3D_COLOR_TEXTURE);
    ffl_print_error(tag);
}

/* The back colors of a pass (see zero_area_note), or NULL. */
static const GLfloat *back_colors;

/* On each vertex of a triangle of exactly zero window-space area (two corners at one
 * position: the poles of a textured gluSphere), " osmesa-exempt=zero-area-facing ref
 * rgba <the vertex's back color>": §2.14.1 gives such a triangle the back colors,
 * OSMesa the front ones (difference 22 in docs/osmesa-differences.md). */
static void zero_area_note(void *user, GLenum token, const GLfloat *vertices,
                           int nverts, int k, GLint offset, GLenum type)
{
    int size = ffl_feedback_vertex_size(type), j;
    double area = 0.0;
    (void)user;
    (void)k;
    if (token != GL_POLYGON_TOKEN || back_colors == NULL)
        return;
    for (j = 0; j < nverts; j++) {
        const GLfloat *p = vertices + j * size, *q = vertices + ((j + 1) % nverts) * size;
        area += (double)p[0] * q[1] - (double)q[0] * p[1];
    }
    if (area != 0.0)
        return;
    printf(" osmesa-exempt=zero-area-facing ref");
    ffl_pfv("rgba", back_colors + offset + 3, 4);
}

static void draw_quadrics(GLUquadric *q, int sphere_and_cylinder)
{
    glNormal3f(0.0f, 0.0f, 1.0f);
    glTexCoord2f(0.5f, 0.5f);
    if (sphere_and_cylinder) {
        gluSphere(q, 1.5, 5, 3);
        glPushMatrix();
        glTranslatef(2.0f, 0.0f, 0.0f);
        gluCylinder(q, 1.0, 0.5, 2.0, 4, 2);
        glPopMatrix();
    }
    glPushMatrix();
    glTranslatef(-2.0f, 1.0f, 0.0f);
    gluDisk(q, 0.25, 1.0, 5, 2);
    glTranslatef(0.0f, -2.5f, 0.0f);
    gluPartialDisk(q, 0.5, 1.25, 4, 2, 30.0, 200.0);
    glPopMatrix();
}

/*
 * Every draw style, normals mode, orientation, texture coordinates on and off.
 * GLU_FILL with normals: a textured sphere's quad strips reach its poles, each pole
 * quad giving a triangle of zero area whose colors are checked against the back
 * colors (zero_area_note); those come from a second pass of the same calls, one-sided,
 * under the modelview mirrored through the origin (glScalef(-1, -1, -1) first): the
 * light is directional and the viewer infinite, so each vertex's color there is the
 * material lit with the negated eye normal, which is the back color (one material for
 * both faces). That pass is printed and compared too.
 * GLU_FLAT in GLU_POINT and GLU_SILHOUETTE styles: libGLU's gluSphere and gluCylinder
 * give normals from stack arrays they never fill (they fill the vertex-normal caches
 * only for GLU_SMOOTH, or GLU_FLAT with GLU_LINE; valgrind reports the reads), so only
 * the disks, whose normals are set, are drawn there.
 */
static void quadrics(void)
{
    static const GLenum styles[4] = { GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT };
    static const GLenum normals[3] = { GLU_NONE, GLU_FLAT, GLU_SMOOTH };
    static GLfloat back[BUF_SIZE];
    GLUquadric *q = gluNewQuadric();
    int style, normal, k = 0;
    for (style = 0; style < 4; style++)
        for (normal = 0; normal < 3; normal++, k++) {
            int all = !(normals[normal] == GLU_FLAT &&
                        (styles[style] == GLU_POINT || styles[style] == GLU_SILHOUETTE));
            GLint n, n_back = -1;
            char tag[64];
            gluQuadricDrawStyle(q, styles[style]);
            gluQuadricNormals(q, normals[normal]);
            gluQuadricOrientation(q, k % 2 ? GLU_INSIDE : GLU_OUTSIDE);
            gluQuadricTexture(q, (GLboolean)(k % 3 != 0));
            if (styles[style] == GLU_FILL) {
                glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
                glPushMatrix();
                glScalef(-1.0f, -1.0f, -1.0f);
                start(back);
                draw_quadrics(q, all);
                n_back = glRenderMode(GL_RENDER);
                glPopMatrix();
                glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
                sprintf(tag, "quadric_style%d_normals%d_back", style, normal);
                ffl_print_feedback_segments(tag, back, n_back, GL_3D_COLOR_TEXTURE);
            }
            start(buf);
            draw_quadrics(q, all);
            n = glRenderMode(GL_RENDER);
            sprintf(tag, "quadric_style%d_normals%d", style, normal);
            /* the back pass has the same tokens, vertex for vertex */
            back_colors = n == n_back ? back : NULL;
            ffl_print_feedback_segments_note(tag, buf, n, GL_3D_COLOR_TEXTURE, zero_area_note,
                                             NULL);
            back_colors = NULL;
            ffl_print_error(tag);
        }
    gluDeleteQuadric(q);
}

static GLdouble combined[64][3];
static int ncombined;

static void GLAPIENTRY combine(GLdouble coords[3], void *data[4], GLfloat weight[4],
                               void **out)
{
    (void)data;
    (void)weight;
    if (ncombined >= 64) {
        *out = combined[63];
        return;
    }
    combined[ncombined][0] = coords[0];
    combined[ncombined][1] = coords[1];
    combined[ncombined][2] = coords[2];
    *out = combined[ncombined++];
}

static int edge_flags[2];

static void GLAPIENTRY edge_flag(GLboolean flag)
{
    edge_flags[flag ? 1 : 0]++;
    glEdgeFlag(flag);
}

static void tessellate(GLUtesselator *tess, GLenum winding)
{
    static GLdouble outer[6][3] = {
        { -3, -3, 0 }, { 3, -3, 0 }, { 3, 3, 0 }, { 0, 0.5, 0 }, { -3, 3, 0 }, { -2, 0, 0 },
    };
    static GLdouble hole[4][3] = {
        { -1, -2, 0 }, { -1, -1, 0 }, { 1, -1, 0 }, { 1, -2, 0 },
    };
    int k;
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, winding);
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (k = 0; k < 6; k++)
        gluTessVertex(tess, outer[k], outer[k]);
    gluTessEndContour(tess);
    gluTessBeginContour(tess);
    for (k = 0; k < 4; k++)
        gluTessVertex(tess, hole[k], hole[k]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

static void tessellator(void)
{
    static const GLenum rules[5] = { GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
                                     GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE,
                                     GLU_TESS_WINDING_ABS_GEQ_TWO };
    static GLdouble star[5][3] = {
        { 0, 3, 0 }, { 1.8, -2.4, 0 }, { -2.9, 0.9, 0 }, { 2.9, 0.9, 0 }, { -1.8, -2.4, 0 },
    };
    GLUtesselator *tess = gluNewTess();
    int r, k;
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)glEnd);
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG, (_GLUfuncptr)edge_flag);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combine);
    gluTessNormal(tess, 0, 0, 1);
    for (r = 0; r < 5; r++) {
        char tag[64];
        edge_flags[0] = edge_flags[1] = 0;
        start(buf);
        tessellate(tess, rules[r]);
        sprintf(tag, "tess_rule%d", r);
        finish(tag);
        printf("%s edge flags false %d true %d\n", tag, edge_flags[0], edge_flags[1]);
    }
    for (r = 0; r < 2; r++) {
        char tag[64];
        ncombined = 0;
        gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[r]);
        start(buf);
        gluTessBeginPolygon(tess, NULL);
        gluTessBeginContour(tess);
        for (k = 0; k < 5; k++)
            gluTessVertex(tess, star[k], star[k]);
        gluTessEndContour(tess);
        gluTessEndPolygon(tess);
        sprintf(tag, "star_rule%d", r);
        finish(tag);
        printf("star_rule%d combined %d\n", r, ncombined);
    }
    gluDeleteTess(tess);
}

int main(void)
{
    static const GLfloat light_position[4] = { 1, 2, 3, 0 };
    static const GLfloat specular[4] = { 0.5f, 0.5f, 0.5f, 1 };
    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-5, 5, -5, 5, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(25.0f, 1.0f, 0.3f, 0.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_NORMALIZE);
    quadrics();
    glDisable(GL_LIGHTING);
    glColor3f(0.25f, 0.5f, 1.0f);
    tessellator();
    return 0;
}
