/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: two-sided lighting with glColorMaterial(GL_BACK, mode)
 * (§2.14.3, §2.14.1). While GL_COLOR_MATERIAL is enabled the back material's
 * tracked property is the current color, and a back-facing polygon is lit
 * with the back material. With GL_BACK alone tracking GL_AMBIENT,
 * GL_DIFFUSE, GL_SPECULAR or GL_AMBIENT_AND_DIFFUSE, OSMesa's back color is
 * right in red and wrong in green and blue (it tracks GL_EMISSION, and
 * GL_FRONT_AND_BACK, correctly: shown for contrast). glGetMaterialfv reports
 * the right back material in both (color_material_modes.c): the difference
 * is in the lighting. Back-facing triangles (and a front-facing one), a
 * color per vertex, lit by a directional and a point light; each vertex
 * carries the reference's color.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"
#include "reference/vertex_ref.h"

#define BUF_SIZE 4096

static vref_set vref;

static int pass(const char *tag, ref_state *ref)
{
    static GLfloat buf[BUF_SIZE];
    static const float colors[6][4] = {
        { 0.2f, 0.4f, 0.6f, 1 }, { 0.7f, 0.3f, 0.1f, 0.8f }, { 0.1f, 0.9f, 0.5f, 0.6f },
        { 0.5f, 0.5f, 0.2f, 1 }, { 0.3f, 0.2f, 0.8f, 0.9f }, { 0.9f, 0.1f, 0.3f, 0.7f },
    };
    static const float back[6][2] = { { -8, -2 }, { -8, 6 }, { -2, -2 },   /* clockwise */
                                      { 1, 1 }, { 2, 7 }, { 8, 2 } };      /* clockwise */
    static const float front[3][2] = { { -6, -8 }, { 0, -8 }, { -3, -4 } }; /* counterclockwise */
    ffl_fb fb;
    int k;
    mirror_read_stored_state(ref);
    vref_start(&vref, ref);
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, BUF_SIZE, GL_3D_COLOR);
    ffl_fb_begin(&fb, GL_TRIANGLES);
    mirror_normal3f(ref, 0.1f, 0.2f, 1);
    for (k = 0; k < 6; k++) {
        mirror_color4f(ref, colors[k][0], colors[k][1], colors[k][2], colors[k][3]);
        vref_vertex3f(&vref, back[k][0], back[k][1], 0);
    }
    for (k = 0; k < 3; k++) {
        mirror_color4f(ref, colors[k][0], colors[k][1], colors[k][2], colors[k][3]);
        vref_vertex3f(&vref, front[k][0], front[k][1], 0);
    }
    glEnd();
    return ffl_fb_finish(&fb, tag, vref_note, &vref);
}

int main(void)
{
    static const GLenum faces[2] = { GL_BACK, GL_FRONT_AND_BACK };
    static const char *face_names[2] = { "back", "front_and_back" };
    static const GLenum modes[5] = { GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE,
                                     GL_EMISSION };
    static const char *mode_names[5] = { "ambient", "diffuse", "specular", "ambient_and_diffuse",
                                         "emission" };
    ref_state ref;
    char tag[64];
    int f, m, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    mirror_load_identity(&ref);
    /* lights on both sides, so the back faces are lit too */
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.2f, 0.3f, -1, 0);
    mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, 1, -2, 4, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_DIFFUSE, 0.4f, 0.4f, 0.4f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_AMBIENT, 0.2f, 0.1f, 0.1f, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_materialf(&ref, GL_FRONT_AND_BACK, GL_SHININESS, 8);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT1, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (f = 0; f < 2; f++) {
        for (m = 0; m < 5; m++) {
            /* start each from the same materials */
            mirror_enable(&ref, GL_COLOR_MATERIAL, 0);
            mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_AMBIENT, 0.2f, 0.2f, 0.2f, 1);
            mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.8f, 0.8f, 1);
            mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
            mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_EMISSION, 0, 0, 0, 1);
            mirror_color_material(&ref, faces[f], modes[m]);
            mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
            sprintf(tag, "%s_%s", face_names[f], mode_names[m]);
            failed |= pass(tag, &ref);
        }
    }
    return failed;
}
