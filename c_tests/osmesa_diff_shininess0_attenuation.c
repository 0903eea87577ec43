/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: material shininess 0 with an attenuated positional
 * light (or a spot light).
 *
 * The spec's specular term is f_i (n (.) h_i)^0 s_cm s_cli = s_cm s_cli
 * wherever n . VP_pli > 0, scaled by att_i. Mesa's generated vertex program
 * (ffvertex_prog.c), when the shininess of every face in use is 0 and a light
 * needs attenuation or a spot factor, evaluates the power with the exponent
 * taken from n . VP_pli: it gives (n.l)^(n.l) instead of 1.
 *
 * Here: light 0 at (0, 0, 5) in eye space, linear attenuation 0.5 (att =
 * 1 / (1 + 0.5 * 5) = 1 / 3.5), specular only (1, 1, 1); material specular
 * 0.5, shininess 0, no ambient, diffuse or emission. Vertices at the origin
 * with normals at angles whose cosine with the light direction is 1, 0.8,
 * 0.5 and 0.2. Spec: every lit color is 0.5 / 3.5 = 0.142857143.
 * OSMesa: 0.142857143 * c^c for c = n.l, i.e. 0.1428, 0.1195, 0.1010, 0.1032.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float cosines[4] = { 1.0f, 0.8f, 0.5f, 0.2f };
    float vertices[4][3], normals[4][3];
    ref_state ref;
    int k;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0, 0, 5, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_AMBIENT, 0, 0, 0, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0, 0, 0, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
    mirror_lightf(&ref, GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.5f);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_AMBIENT, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_DIFFUSE, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_materialf(&ref, GL_FRONT_AND_BACK, GL_SHININESS, 0.0f);
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (k = 0; k < 4; k++) {
        vertices[k][0] = 0; vertices[k][1] = 0; vertices[k][2] = 0;
        normals[k][0] = (float)sqrt(1.0 - (double)cosines[k] * cosines[k]);
        normals[k][1] = 0;
        normals[k][2] = cosines[k];
    }
    printf("spec_value");
    ffl_pf(0.5 / 3.5);
    printf("\n");
    return mirror_draw_points(&ref, "v", 4, (const float (*)[3])vertices,
                              (const float (*)[3])normals, NULL);
}
