/* ffl-test: differential */
/*
 * Feedback of segments and polygons (§5.3) in every vertex layout: GL_2D,
 * GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE (w is the
 * clip w). glPassThrough markers before, between and after the primitives
 * keep their place in the stream. Lines, a strip, a loop, triangles, a quad
 * and a polygon crossing the view volume of a perspective projection, filled
 * and as outlines, with a viewport offset and a depth range other than
 * [0, 1]; texture coordinates (some with q != 1) are interpolated at the
 * vertices clipping makes, like colors.
 *
 * Then the same inside the view, through a non-identity texture matrix
 * (translation, rotation, non-uniform scale): the fed-back texture
 * coordinates are the transformed ones (§2.11.4: the texture matrix is part
 * of vertex processing; §5.3: feedback returns the processed, clipped
 * vertices). They carry the reference's T (s, t, r, q), T as GL stored it.
 * OSMesa feeds back the untransformed coordinates (osmesa_diff_texture_matrix.c):
 * those lines are marked osmesa-exempt=texture_matrix, their strq compared
 * with the reference only (positions and colors still with OSMesa).
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"

#define BUF_SIZE 8192

#define MAX_VERTICES 64

/* every vertex drawn: its color (unique, so a fed-back vertex that clipping
 * left alone is found by it) and texture coordinate */
static int vertex_number;
static float colors[MAX_VERTICES][4], tex_coords[MAX_VERTICES][4];
static double texture_matrix[16];

static void vertex(float x, float y, float z)
{
    int k = vertex_number++;
    float *c = colors[k], *t = tex_coords[k];
    c[0] = 0.1f + 0.07f * (float)(k % 12);
    c[1] = 0.9f - 0.05f * (float)(k % 15);
    c[2] = 0.3f + 0.1f * (float)(k % 5);
    c[3] = 1.0f - 0.02f * (float)k;
    glColor4fv(c);
    if (k % 3 == 0) {
        t[0] = 0.25f * (float)k; t[1] = 1.0f - 0.1f * (float)k; t[2] = 0.5f; t[3] = 2.0f;
        glTexCoord4fv(t);
    } else {
        t[0] = 0.1f * (float)k; t[1] = -0.3f * (float)k; t[2] = 0.0f; t[3] = 1.0f;
        glTexCoord2f(t[0], t[1]);
    }
    glVertex3f(x, y, z);
}

/* The vertex note: " ref strq T(s t r q) osmesa-exempt=texture_matrix" for a
 * fed-back vertex with a drawn vertex's color. */
static void texture_note(void *user, GLenum mode, GLenum token, const GLfloat *vertices,
                         int nverts, int k, GLenum type)
{
    int size = ffl_feedback_vertex_size(type), at = type == GL_4D_COLOR_TEXTURE ? 4 : 3, i, r;
    const GLfloat *v = vertices + k * size;
    (void)user; (void)mode; (void)token; (void)nverts;
    if (type != GL_3D_COLOR_TEXTURE && type != GL_4D_COLOR_TEXTURE)
        return;
    for (i = 0; i < vertex_number; i++) {
        double expect[4];
        if (memcmp(v + at, colors[i], sizeof colors[i]) != 0)
            continue;
        for (r = 0; r < 4; r++)
            expect[r] = texture_matrix[r] * tex_coords[i][0] +
                        texture_matrix[4 + r] * tex_coords[i][1] +
                        texture_matrix[8 + r] * tex_coords[i][2] +
                        texture_matrix[12 + r] * tex_coords[i][3];
        printf(" ref");
        ffl_pdv("strq", expect, 4);
        printf(" osmesa-exempt=texture_matrix");
        return;
    }
}

/* Everything inside the view volume */
static void draw_inside(ffl_fb *fb)
{
    vertex_number = 0;
    glPassThrough(10.0f);
    ffl_fb_begin(fb, GL_LINES);
    vertex(-1.2f, -0.6f, -6);
    vertex(1.8f, 0.9f, -8);
    glEnd();
    ffl_fb_begin(fb, GL_LINE_LOOP);
    vertex(-0.6f, -0.6f, -5);
    vertex(-1.8f, 1.2f, -6);
    vertex(0.3f, 0.3f, -4);
    glEnd();
    glPassThrough(11.0f);
    ffl_fb_begin(fb, GL_TRIANGLES);
    vertex(-1.2f, -1.2f, -6);
    vertex(1.2f, -0.9f, -6);
    vertex(0, 1.2f, -7);
    glEnd();
    ffl_fb_begin(fb, GL_QUADS);
    vertex(-1.8f, -1.8f, -7);
    vertex(1.8f, -1.5f, -7);
    vertex(1.8f, 1.8f, -9);
    vertex(-1.8f, 1.5f, -9);
    glEnd();
    ffl_fb_begin(fb, GL_POLYGON);
    vertex(-0.6f, -1.2f, -5);
    vertex(1.2f, -0.9f, -5);
    vertex(1.5f, 0, -6);
    vertex(0.6f, 1.2f, -6);
    vertex(-1.2f, 0.6f, -5);
    glEnd();
    glPassThrough(12.0f);
}

static void draw(ffl_fb *fb)
{
    vertex_number = 0;
    glPassThrough(1.5f);
    ffl_fb_begin(fb, GL_LINES);
    vertex(-2, -1, -6);
    vertex(3, 1.5f, -8);
    vertex(-9, 0, -5); /* leaves on the left */
    vertex(1, 1, -5);
    glEnd();
    glPassThrough(2.5f);
    ffl_fb_begin(fb, GL_LINE_STRIP);
    vertex(0, 0, -4);
    vertex(2, -1, -7);
    vertex(1, 3, -30); /* beyond the far plane */
    glEnd();
    ffl_fb_begin(fb, GL_LINE_LOOP);
    vertex(-1, -1, -5);
    vertex(-3, 2, -6);
    vertex(-2, 0.5f, 1); /* behind the eye */
    glEnd();
    glPassThrough(-3.0f);
    ffl_fb_begin(fb, GL_TRIANGLES);
    vertex(-2, -2, -6);
    vertex(2, -1.5f, -6);
    vertex(0, 2, -7);
    vertex(-1, -1, -3);
    vertex(12, 0, -6); /* right */
    vertex(0, 1, -4);
    glEnd();
    ffl_fb_begin(fb, GL_QUADS);
    vertex(-3, -3, -1.5f); /* crosses the near plane */
    vertex(3, -3, -1.5f);
    vertex(3, 3, -9);
    vertex(-3, 3, -9);
    glEnd();
    glPassThrough(4.25f);
    ffl_fb_begin(fb, GL_POLYGON);
    vertex(-1, -4, -5);
    vertex(2, -3.5f, -5);
    vertex(4, 0, -6);
    vertex(1, 5, -6); /* top */
    vertex(-2, 1, -5);
    glEnd();
    glPassThrough(5.0f);
}

int main(void)
{
    static const GLenum types[5] = { GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE,
                                     GL_4D_COLOR_TEXTURE };
    static const char *names[5] = { "2d", "3d", "3d_color", "3d_color_texture",
                                    "4d_color_texture" };
    static GLfloat buf[BUF_SIZE];
    ffl_fb fb;
    int t, line, failed = 0;
    char tag[64];

    ffl_test_init();
    glViewport(4, 8, 56, 48);
    glDepthRange(0.1, 0.8);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -0.8, 0.8, 2, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(5, 0.2f, 1, 0);

    for (line = 0; line < 2; line++) {
        glPolygonMode(GL_FRONT_AND_BACK, line ? GL_LINE : GL_FILL);
        for (t = 0; t < 5; t++) {
            sprintf(tag, "%s_%s", line ? "line" : "fill", names[t]);
            ffl_fb_init(&fb);
            ffl_fb_start(&fb, buf, BUF_SIZE, types[t]);
            draw(&fb);
            failed |= ffl_fb_finish(&fb, tag, NULL, NULL);
        }
    }

    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25f, -0.5f, 0.125f);
    glRotatef(30, 0, 0, 1);
    glScalef(2, 0.5f, 1.5f);
    glMatrixMode(GL_MODELVIEW);
    {
        GLfloat m[16];
        int k;
        glGetFloatv(GL_TEXTURE_MATRIX, m);
        for (k = 0; k < 16; k++)
            texture_matrix[k] = m[k];
    }
    for (line = 0; line < 2; line++) {
        glPolygonMode(GL_FRONT_AND_BACK, line ? GL_LINE : GL_FILL);
        for (t = 0; t < 5; t++) {
            sprintf(tag, "texture_matrix_%s_%s", line ? "line" : "fill", names[t]);
            ffl_fb_init(&fb);
            ffl_fb_start(&fb, buf, BUF_SIZE, types[t]);
            draw_inside(&fb);
            failed |= ffl_fb_finish(&fb, tag, texture_note, NULL);
        }
    }
    return failed;
}
