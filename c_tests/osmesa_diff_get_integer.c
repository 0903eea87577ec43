/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: integer queries of float state (§6.1.2).
 *
 * The spec: a color component read through an integer query maps linearly,
 * 1.0 to the most positive and -1.0 to the most negative integer
 * (-2147483648); any other float state is rounded to the nearest integer.
 * Mesa's glGetLightiv converts colors with (GLint)(c * 2147483647), giving
 * -2147483647 for -1.0, and truncates the other values (a spot exponent of
 * 2.75 reads back as 2, a spot direction component of -0.866 as 0); its
 * glGetMaterialiv rounds the shininess (12.75 reads back as 13, as the spec
 * says) but maps colors like glGetLightiv.
 */
#include "ffl_test.h"
#include <limits.h>

static void show(const char *what, GLenum pname, int n, const GLint *expect)
{
    GLint iv[4] = { -9, -9, -9, -9 };
    int k;
    glGetLightiv(GL_LIGHT1, pname, iv);
    printf("light %s i", what);
    for (k = 0; k < n; k++)
        printf(" %d", (int)iv[k]);
    printf(" ref i");
    for (k = 0; k < n; k++)
        printf(" %d", (int)expect[k]);
    printf("\n");
}

int main(void)
{
    static const GLfloat color[4] = { -1.0f, 1.0f, 0.25f, -0.5f };
    static const GLint color_expect[4] = { INT_MIN, INT_MAX, 536870911, -1073741824 };
    static const GLfloat direction[3] = { 0, -1, -2 };
    static const GLint direction_expect[3] = { 1, 0, -2 };
    static const GLint exponent_expect[1] = { 3 };
    GLfloat cos30 = (GLfloat)cos(30.0 * FFL_PI / 180.0);
    GLint direction2_expect[3];
    GLint iv[1];

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* spec: c -> ((2^32 - 1) c - 1) / 2, rounded: -1.0 -> -2^31;
     * 0.25 -> 536870911.375; -0.5 -> -1073741824.25. (0.0 gives -0.5, a
     * tie, so it is not used.) */
    glLightfv(GL_LIGHT1, GL_DIFFUSE, color);
    show("diffuse", GL_DIFFUSE, 4, color_expect);

    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.75f);
    show("spot_exponent_2.75", GL_SPOT_EXPONENT, 1, exponent_expect);

    /* (0, -1, -2) rotated 90 degrees about z is (1, 0, -2) up to rounding */
    glRotatef(90, 0, 0, 1);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, direction);
    show("spot_direction_rotated_90", GL_SPOT_DIRECTION, 3, direction_expect);

    /* rotated 30 degrees: (0.5, -0.866, -2) rounds to (1 or 0, -1, -2); the
     * tie at 0.5 is avoided by reading the y and z components only */
    glLoadIdentity();
    glRotatef(30, 0, 0, 1);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, direction);
    direction2_expect[0] = (GLint)floor(-cos30 + 0.5);
    direction2_expect[1] = -2;
    {
        GLint got[3] = { -9, -9, -9 };
        glGetLightiv(GL_LIGHT1, GL_SPOT_DIRECTION, got);
        printf("light spot_direction_rotated_30_yz i %d %d ref i %d %d\n", (int)got[1],
               (int)got[2], (int)direction2_expect[0], (int)direction2_expect[1]);
    }

    glMaterialf(GL_FRONT, GL_SHININESS, 12.75f);
    glGetMaterialiv(GL_FRONT, GL_SHININESS, iv);
    printf("material shininess_12.75 i %d ref i 13\n", (int)iv[0]);
    glMaterialfv(GL_FRONT, GL_EMISSION, color);
    {
        GLint got[4] = { -9, -9, -9, -9 };
        glGetMaterialiv(GL_FRONT, GL_EMISSION, got);
        printf("material emission i %d %d %d %d ref i %d %d %d %d\n", (int)got[0], (int)got[1],
               (int)got[2], (int)got[3], (int)color_expect[0], (int)color_expect[1],
               (int)color_expect[2], (int)color_expect[3]);
    }
    printf("error %s\n", ffl_error_name(glGetError()));
    return 0;
}
