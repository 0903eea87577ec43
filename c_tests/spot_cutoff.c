/* ffl-test: differential */
/*
 * Spot lights (§2.14.1): the cone test against cos(cutoff), the exponent,
 * the spot factor scaling the ambient term too, the spot direction
 * transformed by the modelview in force at glLight time, cutoff 90 and 180,
 * and a spot cone on a directional light (the spot factor then depends on
 * the light direction only).
 *
 * Light 0 sits at (0, 0, 10) in eye space; its spot direction is given as
 * (0, 0, -1) under a rotation, so in eye space it is that rotation of -z.
 * Vertices lie 6 units from the light at known angles from the spot axis
 * (never within a degree of a cutoff: the spec's >= and Mesa's > differ only
 * on the boundary), each with the normal facing the light, so n . L = 1 and
 * the color is spot * (ambient + diffuse).
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

static const double angles[] = { 0, 3, 9, 11, 29, 31, 44, 46, 60, 85, 89, 91, 120, 170 };
#define NUM_ANGLES ((int)(sizeof angles / sizeof angles[0]))

static void cross(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Draws one point per angle, `distance` from the light position `origin`
 * along the spot axis tilted by the angle. */
static int draw_fan(ref_state *ref, const char *tag, const double *origin, double distance)
{
    float vertices[NUM_ANGLES][3], normals[NUM_ANGLES][3];
    double axis[3], perp[3], up[3] = { 0.3, 1, 0.2 };
    int i, k;
    for (k = 0; k < 3; k++)
        axis[k] = ref->light[0].spot_direction[k];
    ref_normalize3(axis);
    cross(axis, up, perp);
    ref_normalize3(perp);
    for (i = 0; i < NUM_ANGLES; i++) {
        double t = angles[i] * FFL_PI / 180.0;
        for (k = 0; k < 3; k++) {
            double dir = cos(t) * axis[k] + sin(t) * perp[k];
            vertices[i][k] = (float)(origin[k] + distance * dir);
            normals[i][k] = (float)-dir;
        }
    }
    return mirror_draw_points(ref, tag, NUM_ANGLES, (const float (*)[3])vertices,
                              (const float (*)[3])normals, NULL);
}

int main(void)
{
    static const float cutoffs[] = { 10, 30, 45, 90, 180, 0.5f };
    static const float exponents[] = { 0, 2, 20, 128 };
    double origin[3] = { 0, 0, 10 };
    ref_state ref;
    char tag[64];
    int c, e, failed = 0;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);

    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0, 0, 10, 1);
    mirror_rotatef(&ref, 25, 1, 0.5f, 0);
    {
        float dir[3] = { 0, 0, -1 };
        mirror_lightfv(&ref, GL_LIGHT0, GL_SPOT_DIRECTION, dir);
    }
    mirror_load_identity(&ref);
    mirror_light4f(&ref, GL_LIGHT0, GL_AMBIENT, 0.1f, 0.15f, 0.2f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.8f, 0.7f, 0.6f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0, 0, 0, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_AMBIENT, 1, 1, 1, 1);
    mirror_material4f(&ref, GL_FRONT_AND_BACK, GL_DIFFUSE, 1, 1, 1, 1);
    mirror_light_model4f(&ref, GL_LIGHT_MODEL_AMBIENT, 0, 0, 0, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);

    for (c = 0; c < (int)(sizeof cutoffs / sizeof cutoffs[0]); c++) {
        mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_CUTOFF, cutoffs[c]);
        for (e = 0; e < (int)(sizeof exponents / sizeof exponents[0]); e++) {
            mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_EXPONENT, exponents[e]);
            sprintf(tag, "cutoff_%g_exponent_%g", cutoffs[c], exponents[e]);
            failed |= draw_fan(&ref, tag, origin, 6.0);
        }
    }

    /* Attenuation and the spot factor multiply. */
    mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_CUTOFF, 45);
    mirror_lightf(&ref, GL_LIGHT0, GL_SPOT_EXPONENT, 3);
    mirror_lightf(&ref, GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.02f);
    failed |= draw_fan(&ref, "attenuated_spot", origin, 6.0);
    mirror_lightf(&ref, GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);

    /* A directional light with a spot cone: -L . s is the same at every
     * vertex, inside (first light direction) or outside the cone. */
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 0.2f, 0.1f, 1, 0);
    {
        float dir[3] = { 0, 0, -1 };
        mirror_lightfv(&ref, GL_LIGHT0, GL_SPOT_DIRECTION, dir);
    }
    failed |= draw_fan(&ref, "directional_inside", origin, 6.0);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 1, 0.1f, 0.5f, 0);
    failed |= draw_fan(&ref, "directional_outside", origin, 6.0);
    return failed;
}
