/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: the facing of a triangle of zero area (two of its vertices at the
 * same window position), found by the differential sequence fuzzer (tests/osmesa_fuzz.rs,
 * seeds 161 and 187: an indexed strip and fan repeating an index, two-sided lighting).
 *
 * §3.5.1 (which §2.14.1's two-sided lighting uses): "If this sign [of the area a] is
 * positive, the polygon is front facing; otherwise, it is back facing." A zero area is not
 * positive under either glFrontFace: the triangle is back facing, lit with the back
 * material, and culled by glCullFace(GL_BACK). Mesa's draw module culls it as the spec does
 * (glCullFace(GL_BACK) drops it, GL_FRONT keeps it), but its two-sided lighting stage takes
 * a zero determinant as front facing and gives it the front colors, under either
 * glFrontFace.
 *
 * Here: lighting on with no light and no ambient, so each face's color is its emission:
 * front red, back blue. A counterclockwise triangle is red and a clockwise one blue in both
 * libraries (controls); a triangle with two equal vertices, and one with three collinear
 * vertices, are blue by the spec and red in OSMesa; culled with GL_BACK, both libraries feed
 * back nothing for it; culled with GL_FRONT, blue by the spec and red in OSMesa.
 */
#include "ffl_test.h"

static const GLfloat red[4] = { 1, 0, 0, 1 };
static const GLfloat blue[4] = { 0, 0, 1, 1 };

/* Feeds back one triangle and prints its vertices with the expected color. */
static int triangle(const char *name, const float v[3][2], const GLfloat *expected, int cull)
{
    GLfloat buffer[64];
    GLint n, i, k;
    glFeedbackBuffer(64, GL_3D_COLOR, buffer);
    glRenderMode(GL_FEEDBACK);
    if (cull)
        glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    for (k = 0; k < 3; k++)
        glVertex2f(v[k][0], v[k][1]);
    glEnd();
    glDisable(GL_CULL_FACE);
    n = glRenderMode(GL_RENDER);
    printf("%s values %d ref values %d\n", name, (int)n, expected == NULL ? 0 : 23);
    for (i = 2; expected != NULL && i + 7 <= n; i += 7) {
        printf("%s v", name);
        ffl_pfv("xyz", buffer + i, 3);
        ffl_pfv("rgba", buffer + i + 3, 4);
        printf(" ref");
        ffl_pfv("rgba", expected, 4);
        printf("\n");
    }
    return n < 0;
}

int main(void)
{
    static const GLfloat black[4] = { 0, 0, 0, 1 };
    static const float ccw[3][2] = { { 0, 0 }, { 0.5f, 0 }, { 0, 0.5f } };
    static const float cw[3][2] = { { 0, 0 }, { 0, 0.5f }, { 0.5f, 0 } };
    static const float zero_area[3][2] = { { 0, 0 }, { 0.5f, 0.25f }, { 0.5f, 0.25f } };
    static const float collinear[3][2] = { { 0, 0 }, { 0.25f, 0.25f }, { 0.5f, 0.5f } };
    int failed = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, black);
    glMaterialfv(GL_FRONT, GL_EMISSION, red);
    glMaterialfv(GL_BACK, GL_EMISSION, blue);

    failed |= triangle("ccw", ccw, red, 0);
    failed |= triangle("cw", cw, blue, 0);
    failed |= triangle("zero_area", zero_area, blue, 0);
    failed |= triangle("collinear", collinear, blue, 0);
    glFrontFace(GL_CW);
    failed |= triangle("zero_area_front_cw", zero_area, blue, 0);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    failed |= triangle("cull_back_ccw", ccw, red, 1);
    failed |= triangle("cull_back_zero_area", zero_area, NULL, 1);
    glCullFace(GL_FRONT);
    failed |= triangle("cull_front_zero_area", zero_area, blue, 1);
    ffl_print_error("error");
    return failed;
}
