/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: texture coordinates in feedback (§2.11.4, §5.3). The
 * texture matrix (and texture coordinate generation) is part of vertex
 * processing: the coordinates that reach clipping, rasterization and
 * feedback are the transformed ones. OSMesa's feedback returns the
 * coordinates as given to glTexCoord, untransformed. A point, a segment and
 * a triangle, each vertex with its own texture coordinate (some with
 * q != 1), through a texture matrix made of a translation, a rotation and a
 * non-uniform scale; each fed-back vertex carries T (s, t, r, q) as its
 * reference, T as GL stored it. (With an identity texture matrix the two
 * agree: feedback_types_points.c and feedback_types_polygons.c.)
 */
#include "ffl_test.h"

#define BUF_SIZE 1024

static const float tex[6][4] = {
    { 0.5f, 0.25f, 0, 1 }, { 1, 0, 0.5f, 1 }, { 0, 1, 0, 2 },
    { 0.25f, 0.75f, 1, 1 }, { 0.6f, 0.1f, 0.3f, 0.5f }, { 0.9f, 0.9f, 0.9f, 1 },
};
static double texture_matrix[16];

/* the vertex whose texture coordinate it is: by its x (vertex k at x = k) */
static void note(void *user, GLenum mode, GLenum token, const GLfloat *vertices, int nverts,
                 int k, GLenum type)
{
    const GLfloat *v = vertices + k * ffl_feedback_vertex_size(type);
    int i = (int)floor((v[0] - 2.0) / 8.0 + 0.5), r;
    double expect[4];
    (void)user; (void)mode; (void)token; (void)nverts;
    if (i < 0 || i > 5)
        return;
    for (r = 0; r < 4; r++)
        expect[r] = texture_matrix[r] * tex[i][0] + texture_matrix[4 + r] * tex[i][1] +
                    texture_matrix[8 + r] * tex[i][2] + texture_matrix[12 + r] * tex[i][3];
    printf(" ref");
    ffl_pdv("strq", expect, 4);
}

int main(void)
{
    static GLfloat buf[BUF_SIZE];
    GLfloat m[16];
    ffl_fb fb;
    int k, failed;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.25f, -0.5f, 0.125f);
    glRotatef(30, 0, 0, 1);
    glScalef(2, 0.5f, 1.5f);
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    for (k = 0; k < 16; k++)
        texture_matrix[k] = m[k];
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR_TEXTURE);
    ffl_fb_begin(&fb, GL_POINTS);
    glTexCoord4fv(tex[0]);
    glVertex2f(2, 10);
    glEnd();
    ffl_fb_begin(&fb, GL_LINE_STRIP);
    glTexCoord4fv(tex[1]);
    glVertex2f(10, 10);
    glTexCoord4fv(tex[2]);
    glVertex2f(18, 40);
    glEnd();
    ffl_fb_begin(&fb, GL_TRIANGLES);
    for (k = 3; k < 6; k++) {
        glTexCoord4fv(tex[k]);
        glVertex2f(2.0f + 8.0f * (float)k, k == 4 ? 50.0f : 20.0f);
    }
    glEnd();
    failed = ffl_fb_finish(&fb, "texture_matrix", note, NULL);
    return failed;
}
