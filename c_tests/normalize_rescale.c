/* ffl-test: differential */
/*
 * GL_NORMALIZE and GL_RESCALE_NORMAL (§2.11.3): normals are transformed by
 * the inverse of the modelview's upper-left 3x3; then GL_NORMALIZE makes
 * them unit length, GL_RESCALE_NORMAL multiplies them by 1/sqrt(m31^2 +
 * m32^2 + m33^2) of the inverse, and with neither the transformed normal is
 * used as it is (non-unit normals scale the diffuse term). Uniform and
 * non-uniform scales, a rotation, normals of lengths 0.5, 1 and 2; every
 * combination of the two enables. The light is dim so that results stay
 * below 1 and show the normal's length.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float vertices[6][3] = {
        { 0, 0, 0 }, { 1, 2, 3 }, { -2, 1, 0 }, { 3, -1, -2 }, { 0, -3, 1 }, { -1, -1, -1 },
    };
    static const float normals[6][3] = {
        { 0, 0, 1 }, { 0, 0, 0.5f }, { 0, 0, 2 }, { 0.6f, 0, 0.8f }, { 0.3f, 0.4f, 1.2f }, { -0.5f, 0.5f, 1.0f },
    };
    ref_state ref;
    int m, normalize, rescale, failed = 0;
    char tag[96];

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.1f, 0.2f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.1f, 0.12f, 0.14f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT, GL_DIFFUSE, 1, 1, 1, 1);
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (m = 0; m < 5; m++) {
        static const char *names[5] = { "identity", "uniform_2", "uniform_0.5",
                                        "nonuniform_1_2_3", "rotated_uniform_3" };
        mirror_load_identity(&ref);
        switch (m) {
        case 1: mirror_scalef(&ref, 2, 2, 2); break;
        case 2: mirror_scalef(&ref, 0.5f, 0.5f, 0.5f); break;
        case 3: mirror_scalef(&ref, 1, 2, 3); break;
        case 4:
            mirror_rotatef(&ref, 40, 0.2f, 1, 0.3f);
            mirror_scalef(&ref, 3, 3, 3);
            break;
        default: break;
        }
        for (normalize = 0; normalize < 2; normalize++) {
            for (rescale = 0; rescale < 2; rescale++) {
                mirror_enable(&ref, GL_NORMALIZE, normalize);
                mirror_enable(&ref, GL_RESCALE_NORMAL, rescale);
                sprintf(tag, "%s_normalize_%d_rescale_%d", names[m], normalize, rescale);
                failed |= mirror_draw_points(&ref, tag, 6, vertices, normals, NULL);
            }
        }
    }
    return failed;
}
