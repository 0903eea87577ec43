/* ffl-test: differential */
/*
 * GL_LIGHT_MODEL_COLOR_CONTROL (§2.14.1): with GL_SEPARATE_SPECULAR_COLOR
 * the specular sum goes to the secondary color, and feedback (GL_3D_COLOR)
 * reports the primary color only, so the fed-back color loses the specular
 * term; with GL_SINGLE_COLOR it is part of the primary color. Strong
 * specular lighting makes the difference large; with lighting disabled the
 * setting changes nothing.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float vertices[5][3] = {
        { 0, 0, 0 }, { 4, 2, -3 }, { -6, 1, 2 }, { 2, -5, 5 }, { -3, -3, -8 },
    };
    static const float normals[5][3] = {
        { 0, 0, 1 }, { 0.2f, 0.1f, 1 }, { -0.3f, 0.2f, 0.9f }, { 0.1f, -0.4f, 0.9f }, { 0.5f, 0.5f, 0.7f },
    };
    static const float colors[5][4] = {
        { 0.1f, 0.2f, 0.3f, 1 }, { 0.4f, 0.5f, 0.6f, 0.5f }, { 0.9f, 0.1f, 0.5f, 0.25f },
        { 0.3f, 0.3f, 0.3f, 1 }, { 0.7f, 0.6f, 0.2f, 0.8f },
    };
    ref_state ref;
    int lighting, separate, failed = 0;
    char tag[64];

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.1f, 0.2f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.3f, 0.3f, 0.3f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.6f, 0.5f, 0.4f, 1);
    mirror_light4f(&ref, GL_LIGHT2, GL_POSITION, 5, 5, 20, 1);
    mirror_light4f(&ref, GL_LIGHT2, GL_DIFFUSE, 0.1f, 0.1f, 0.1f, 1);
    mirror_light4f(&ref, GL_LIGHT2, GL_SPECULAR, 0.3f, 0.2f, 0.1f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 0.7f, 0.8f, 0.9f, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 8);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT2, 1);
    mirror_enable(&ref, GL_NORMALIZE, 1);

    for (lighting = 0; lighting < 2; lighting++) {
        mirror_enable(&ref, GL_LIGHTING, lighting);
        for (separate = 0; separate < 2; separate++) {
            mirror_light_modeli(&ref, GL_LIGHT_MODEL_COLOR_CONTROL,
                                separate ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
            sprintf(tag, "lighting_%d_%s", lighting, separate ? "separate" : "single");
            failed |= mirror_draw_points(&ref, tag, 5, vertices, normals, colors);
        }
    }
    /* color material on the specular color with separate specular */
    mirror_enable(&ref, GL_LIGHTING, 1);
    mirror_color_material(&ref, GL_FRONT, GL_SPECULAR);
    mirror_enable(&ref, GL_COLOR_MATERIAL, 1);
    failed |= mirror_draw_points(&ref, "separate_color_material_specular", 5, vertices, normals,
                                 colors);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
    failed |= mirror_draw_points(&ref, "single_color_material_specular", 5, vertices, normals,
                                 colors);
    return failed;
}
