/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: front shininess 0 where n . h_i <= 0 < n . VP_pli,
 * with two-sided lighting on and a nonzero back shininess.
 *
 * The spec's specular term is f_i (n (.) h_i)^0 s_cm s_cli with f_i = 1
 * (n . VP_pli > 0) and n (.) h_i = max(n . h_i, 0) = 0: the power is 0^0,
 * taken as 1 (the limit of x^s as s goes to 0, C's pow(0, 0), and what
 * Mesa itself computes when every shininess in use is 0). Mesa's generated
 * vertex program only takes its shininess-0 shortcut when the back
 * shininess is 0 as well (with two-sided lighting); otherwise it evaluates
 * the power for the front face and gets 0^0 = 0: the specular term vanishes.
 *
 * Here: directional light 0 towards (1, 0, -0.2), specular only (1, 1, 1);
 * infinite viewer, so h = normalize(VP + (0, 0, 1)); front material specular
 * 0.5 and shininess 0, back shininess 10; the normal (0.5, 0, -0.866) has
 * n . VP = 0.66 > 0 and n . h = -0.16 < 0. Spec: 0.5; OSMesa: 0.
 * The second point has n . h > 0 and both agree (0.5); the third point is
 * lit with two-sided lighting off, where Mesa takes the shortcut (0.5).
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float vertices[2][3] = { { 0, 0, 0 }, { 1, 1, 0 } };
    static const float normals[2][3] = { { 0.5f, 0.0f, -0.8660254f }, { 0.6f, 0.0f, 0.8f } };
    ref_state ref;
    int failed;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 1, 0, -0.2f, 0);
    mirror_light4f(&ref, GL_LIGHT0, GL_AMBIENT, 0, 0, 0, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0, 0, 0, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 1, 1, 1, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_AMBIENT, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_DIFFUSE, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 0.0f);
    mirror_materialf(&ref, GL_BACK, GL_SHININESS, 10.0f);
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    printf("spec_value");
    ffl_pf(0.5);
    printf("\n");
    failed = mirror_draw_points(&ref, "two_side", 2, vertices, normals, NULL);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_TWO_SIDE, 0);
    failed |= mirror_draw_points(&ref, "one_side", 1, vertices, normals, NULL);
    return failed;
}
