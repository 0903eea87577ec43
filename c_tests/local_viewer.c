/* ffl-test: differential */
/*
 * GL_LIGHT_MODEL_LOCAL_VIEWER (§2.14.1): the half vector uses the direction
 * from the vertex to the eye, normalize(-V), instead of (0, 0, 1). Vertices
 * far from the z axis make the two differ; a directional and a point light,
 * two shininesses, specular-dominated colors.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float shininess[] = { 5, 60 };
    float vertices[20][3], normals[20][3];
    ref_state ref;
    char tag[64];
    int i, s, local, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    for (i = 0; i < 20; i++) {
        vertices[i][0] = -40.0f + 20.0f * (float)(i % 5);
        vertices[i][1] = (i / 5) % 2 ? 25.0f : -15.0f;
        vertices[i][2] = i < 10 ? -20.0f : -60.0f;
        normals[i][0] = 0.1f * (float)(i % 3) - 0.1f;
        normals[i][1] = 0.05f * (float)(i % 4);
        normals[i][2] = 1.0f;
    }

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.3f, 0.2f, 1, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.1f, 0.1f, 0.1f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.6f, 0.5f, 0.4f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_POSITION, -10, 20, 30, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_DIFFUSE, 0.1f, 0.1f, 0.1f, 1);
    mirror_light4f(&ref, GL_LIGHT1, GL_SPECULAR, 0.3f, 0.4f, 0.5f, 1);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 1, 1, 1, 1);
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, 0.05f, 0.05f, 0.05f, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHT1, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);
    mirror_enable(&ref, GL_NORMALIZE, 1);

    for (local = 0; local < 2; local++) {
        mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, local);
        for (s = 0; s < 2; s++) {
            mirror_materialf(&ref, GL_FRONT, GL_SHININESS, shininess[s]);
            sprintf(tag, "local_viewer_%d_shininess_%g", local, shininess[s]);
            failed |= mirror_draw_points(&ref, tag, 20, (const float (*)[3])vertices,
                                         (const float (*)[3])normals, NULL);
        }
    }
    /* The same state, the eye moved by the modelview instead. */
    mirror_translatef(&ref, 15, -10, -5);
    sprintf(tag, "local_viewer_1_translated");
    failed |= mirror_draw_points(&ref, tag, 20, (const float (*)[3])vertices,
                                 (const float (*)[3])normals, NULL);
    return failed;
}
