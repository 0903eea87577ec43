/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: lighting a vertex given with w != 1.
 *
 * The spec lights the vertex at its eye-space position V; a homogeneous
 * point (x, y, z, w) is the point (x/w, y/w, z/w), so (1, -1, -2, 1),
 * (2, -2, -4, 2) and (0.5, -0.5, -1, 0.5) are the same point and get the
 * same color. Mesa's generated vertex program subtracts the eye-space
 * position from the light position component-wise without dividing by w
 * (and normalizes -V.xyz for the local viewer), so the three differ:
 * the vector to the light, the distance for attenuation and the half vector
 * are those of (x, y, z) instead of (x/w, y/w, z/w).
 *
 * Here: positional light at (2, 3, 4) with linear attenuation 0.2, local
 * viewer, diffuse and specular (shininess 10). Window coordinates agree
 * (the perspective division is right); the colors differ.
 */
#include "ffl_test.h"
#include "reference/gl_mirror.h"

int main(void)
{
    static const float vertices[3][4] = {
        { 1, -1, -2, 1 }, { 2, -2, -4, 2 }, { 0.5f, -0.5f, -1, 0.5f },
    };
    ref_state ref;
    GLfloat buf[64];
    double expect[3][4], secondary[4];
    GLint n;
    int k;

    ffl_test_init();
    ref_init(&ref);
    mirror_standard_view(&ref);
    mirror_light4f(&ref, GL_LIGHT0, GL_POSITION, 2, 3, 4, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_DIFFUSE, 0.5f, 0.5f, 0.5f, 1);
    mirror_light4f(&ref, GL_LIGHT0, GL_SPECULAR, 0.5f, 0.5f, 0.5f, 1);
    mirror_lightf(&ref, GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.2f);
    mirror_material4f(&ref, GL_FRONT, GL_SPECULAR, 1, 1, 1, 1);
    mirror_materialf(&ref, GL_FRONT, GL_SHININESS, 10);
    mirror_light_modeli(&ref, GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    mirror_enable(&ref, GL_LIGHT0, 1);
    mirror_enable(&ref, GL_LIGHTING, 1);
    printf("stored_state");
    mirror_print_deviation(mirror_read_stored_state(&ref));
    printf("\n");

    glFeedbackBuffer(64, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    mirror_normal3f(&ref, 0.3f, 0.2f, 0.93f);
    for (k = 0; k < 3; k++) {
        double obj[4];
        int c;
        glVertex4fv(vertices[k]);
        for (c = 0; c < 4; c++)
            obj[c] = vertices[k][c];
        ref_lit_color(&ref, obj, 0, expect[k], secondary);
    }
    glEnd();
    n = glRenderMode(GL_RENDER);
    printf("count %d\n", (int)n);
    if (n != 24)
        return 1;
    for (k = 0; k < 3; k++) {
        printf("w_%g", vertices[k][3]);
        ffl_pfv("xyz", buf + k * 8 + 1, 3);
        ffl_pfv("rgba", buf + k * 8 + 4, 4);
        printf(" ref");
        ffl_pdv("rgba", expect[k], 4);
        printf("\n");
    }
    return 0;
}
