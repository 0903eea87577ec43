/*
 * gl_mirror.h - GL calls made together with their reference mirror.
 *
 * Each mirror_* function makes one GL call and the matching ref_* call with
 * the same arguments, so the reference keeps the state the program set.
 * mirror_draw_points draws vertices as GL_POINTS in feedback mode and prints
 * each fed-back vertex with its reference color.
 * Include after ffl_test.h.
 */
#ifndef FFL_GL_MIRROR_H
#define FFL_GL_MIRROR_H

#include "lighting_ref.h"

static inline void mirror_lightfv(ref_state *ref, GLenum light, GLenum pname, const float *p)
{
    glLightfv(light, pname, p);
    ref_lightfv(ref, light, pname, p);
}

static inline void mirror_lightf(ref_state *ref, GLenum light, GLenum pname, float p)
{
    glLightf(light, pname, p);
    ref_lightf(ref, light, pname, p);
}

static inline void mirror_light4f(ref_state *ref, GLenum light, GLenum pname, float a, float b,
                                  float c, float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    mirror_lightfv(ref, light, pname, p);
}

static inline void mirror_materialfv(ref_state *ref, GLenum face, GLenum pname, const float *p)
{
    glMaterialfv(face, pname, p);
    ref_materialfv(ref, face, pname, p);
}

static inline void mirror_materialf(ref_state *ref, GLenum face, GLenum pname, float p)
{
    glMaterialf(face, pname, p);
    ref_materialf(ref, face, pname, p);
}

static inline void mirror_material4f(ref_state *ref, GLenum face, GLenum pname, float a, float b,
                                     float c, float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    mirror_materialfv(ref, face, pname, p);
}

static inline void mirror_light_model4f(ref_state *ref, GLenum pname, float a, float b, float c,
                                        float d)
{
    float p[4];
    p[0] = a; p[1] = b; p[2] = c; p[3] = d;
    glLightModelfv(pname, p);
    ref_light_modelfv(ref, pname, p);
}

static inline void mirror_light_modeli(ref_state *ref, GLenum pname, GLint v)
{
    glLightModeli(pname, v);
    ref_light_modeli(ref, pname, v);
}

static inline void mirror_enable(ref_state *ref, GLenum cap, int on)
{
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
    if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + REF_MAX_LIGHTS)
        ref->light[cap - GL_LIGHT0].enabled = on;
    else if (cap == GL_LIGHTING)
        ref->lighting = on;
    else if (cap == GL_NORMALIZE)
        ref->normalize = on;
    else if (cap == GL_RESCALE_NORMAL)
        ref->rescale_normal = on;
    else if (cap == GL_COLOR_MATERIAL)
        ref_set_color_material_enabled(ref, on);
}

static inline void mirror_color_material(ref_state *ref, GLenum face, GLenum mode)
{
    glColorMaterial(face, mode);
    ref_color_material(ref, face, mode);
}

static inline void mirror_color4f(ref_state *ref, float r, float g, float b, float a)
{
    glColor4f(r, g, b, a);
    ref_color4f(ref, r, g, b, a);
}

static inline void mirror_normal3f(ref_state *ref, float x, float y, float z)
{
    glNormal3f(x, y, z);
    ref_normal3f(ref, x, y, z);
}

/* Modelview matrix operations (the caller has selected GL_MODELVIEW). */
static inline void mirror_load_identity(ref_state *ref)
{
    glLoadIdentity();
    ref_load_identity(ref);
}

static inline void mirror_translatef(ref_state *ref, float x, float y, float z)
{
    glTranslatef(x, y, z);
    ref_translatef(ref, x, y, z);
}

static inline void mirror_rotatef(ref_state *ref, float a, float x, float y, float z)
{
    glRotatef(a, x, y, z);
    ref_rotatef(ref, a, x, y, z);
}

static inline void mirror_scalef(ref_state *ref, float x, float y, float z)
{
    glScalef(x, y, z);
    ref_scalef(ref, x, y, z);
}

static inline void mirror_mult_matrixf(ref_state *ref, const float *m)
{
    glMultMatrixf(m);
    ref_mult_matrixf(ref, m);
}

/* A 64x64 viewport and an orthographic box large enough for every test
 * vertex, with the modelview selected and set to identity (GL and ref). */
static inline void mirror_standard_view(ref_state *ref)
{
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-100, 100, -100, 100, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(ref);
}

#define MIRROR_MAX_POINTS 64

/* Draws n points in feedback mode (GL_3D_COLOR). Before vertex k it sets the
 * normal normals[k] and the color colors[k] when those arrays are given.
 * Prints "<tag> <k> xyz x y z rgba r g b a ref rgba r g b a" per vertex,
 * or a line saying what went wrong. Returns 0 on success. */
static inline int mirror_draw_points(ref_state *ref, const char *tag, int n,
                                     const float (*vertices)[3], const float (*normals)[3],
                                     const float (*colors)[4])
{
    GLfloat buf[MIRROR_MAX_POINTS * 8];
    double expect[MIRROR_MAX_POINTS][4], secondary[4];
    GLint count;
    int k;
    if (n > MIRROR_MAX_POINTS)
        n = MIRROR_MAX_POINTS;
    glFeedbackBuffer(MIRROR_MAX_POINTS * 8, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    for (k = 0; k < n; k++) {
        double obj[4];
        if (normals != NULL)
            mirror_normal3f(ref, normals[k][0], normals[k][1], normals[k][2]);
        if (colors != NULL)
            mirror_color4f(ref, colors[k][0], colors[k][1], colors[k][2], colors[k][3]);
        glVertex3f(vertices[k][0], vertices[k][1], vertices[k][2]);
        obj[0] = vertices[k][0]; obj[1] = vertices[k][1]; obj[2] = vertices[k][2]; obj[3] = 1.0;
        ref_lit_color(ref, obj, 0, expect[k], secondary);
    }
    glEnd();
    count = glRenderMode(GL_RENDER);
    if (count != n * 8) {
        printf("%s feedback_count %d expected %d\n", tag, (int)count, n * 8);
        return 1;
    }
    for (k = 0; k < n; k++) {
        const GLfloat *fb = buf + k * 8;
        if (fb[0] != (GLfloat)GL_POINT_TOKEN) {
            printf("%s %d not_a_point_token\n", tag, k);
            return 1;
        }
        printf("%s %d", tag, k);
        ffl_pfv("xyz", fb + 1, 3);
        ffl_pfv("rgba", fb + 4, 4);
        printf(" ref");
        ffl_pdv("rgba", expect[k], 4);
        printf("\n");
    }
    return 0;
}

#endif /* FFL_GL_MIRROR_H */
