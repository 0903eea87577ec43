/* ffl-test: differential */
/*
 * Two-sided lighting and points: the back color is selected only for
 * back-facing polygons (§2.14.1, §3.5.1), so a point is always lit with the
 * front material and its normal as given, two-sided lighting on or off,
 * whether its normal faces the viewer or not. The back material is set to
 * something very different so that using it would show.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float vertices[6][3] = {
        { 1, 1, -3 }, { 5, 0, 0 }, { 0, 5, 0 }, { -5, -5, 5 }, { 3, -4, -5 }, { -2, 6, 2 },
    };
    static const float normals[6][3] = {
        { 0, 0, 1 }, { 0, 0, -1 }, { 0.6f, 0, 0.8f }, { 0.6f, 0, -0.8f }, { 0, -1, 0 }, { -0.3f, 0.4f, -0.5f },
    };
    ref_state ref;
    int two_side, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    /* one light from the front, one from behind */
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.2f, 0.3f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.4f, 0.3f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.3f, 0.3f, 0.3f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, -0.1f, 0.2f, -1, 0);
    mirror_light4f(&ref, GL_LIGHT1, GL_DIFFUSE, 0.2f, 0.3f, 0.5f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_SPECULAR, 0.2f, 0.2f, 0.2f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_AMBIENT, 0.3f, 0.1f, 0.1f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_DIFFUSE, 0.8f, 0.3f, 0.2f, 0.75f);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_EMISSION, 0.05f, 0, 0, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 12);
    mirror_material4f(&ref, GL_BACK, GL_AMBIENT, 0.1f, 0.1f, 0.4f, 1);
    mirror_material4f(&ref, GL_BACK, GL_DIFFUSE, 0.1f, 0.2f, 0.9f, 0.25f);
    mirror_material4f(&ref, GL_BACK, GL_SPECULAR, 0.1f, 0.1f, 0.1f, 1);
    mirror_material4f(&ref, GL_BACK, GL_EMISSION, 0, 0, 0.2f, 1);
    mirror_materialf(&ref, GL_BACK, GL_SHININESS, 90);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT1, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (two_side = 0; two_side < 2; two_side++) {
        mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, two_side);
        failed |= mirror_draw_points(&ref, two_side ? "two_side" : "one_side", 6, vertices,
                                     normals, NULL);
        /* local viewer and a positional light as well */
        mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
        mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, 2, -3, -20, 1);
        failed |= mirror_draw_points(&ref, two_side ? "two_side_local" : "one_side_local", 6,
                                     vertices, normals, NULL);
        mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, 0);
        mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, -0.1f, 0.2f, -1, 0);
    }
    return failed;
}
