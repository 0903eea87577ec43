/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: signed integer color and normal arrays.
 *
 * Table 2.9 maps a signed b-bit integer c to (2c + 1) / (2^b - 1), for the
 * immediate-mode commands and the vertex arrays alike (§2.8: an array element
 * is the same as the command it stands for). OSMesa does so for glColor4bv,
 * glNormal3bv and glArrayElement, but its array draws normalize as GL 4.2
 * does, max(c / (2^(b-1) - 1), -1): -1 becomes -0.0079 instead of -0.0039,
 * 0 becomes 0 instead of 0.0039. fflight gives array draws exactly the
 * immediate-mode values.
 *
 * Here: colors of GL_BYTE, GL_SHORT and GL_INT drawn unlit with glDrawArrays
 * into feedback (GL_3D_COLOR, clamped to [0, 1]): OSMesa differs; normals of
 * the same types made current with glArrayElement and read back with
 * glGetFloatv(GL_CURRENT_NORMAL): OSMesa agrees.
 */
#include "ffl_test.h"
#include <limits.h>

#define N 4

static double signed_to_float(double c, double bits)
{
    return (2.0 * c + 1.0) / (pow(2.0, bits) - 1.0);
}

static double clamp01(double v)
{
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

int main(void)
{
    static const GLbyte bytes[N * 4] = { -128, -1, 0, 127, 1, 64, -64, 100,
                                         0, 0, 0, 0, 127, 127, -1, 0 };
    static const GLshort shorts[N * 4] = { SHRT_MIN, -1, 0, SHRT_MAX, 1, 16384, -16384, 1000,
                                           0, 0, 0, 0, SHRT_MAX, 3, -1, 0 };
    static const GLint ints[N * 4] = { INT_MIN, -1, 0, INT_MAX, 1, 1 << 30, -(1 << 30), 1000,
                                       0, 0, 0, 0, INT_MAX, 3, -1, 0 };
    static const GLfloat positions[N * 3] = { 0, 0, 0, 0.5f, 0, 0, 0, 0.5f, 0, -0.5f, 0, 0 };
    const void *data[3] = { bytes, shorts, ints };
    static const GLenum types[3] = { GL_BYTE, GL_SHORT, GL_INT };
    static const char *names[3] = { "byte", "short", "int" };
    static const double bits[3] = { 8, 16, 32 };
    GLfloat buf[64];
    int t, i, c;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glEnableClientState(GL_VERTEX_ARRAY);
    for (t = 0; t < 3; t++) {
        double value[4];
        GLint n;
        glColorPointer(4, types[t], 0, data[t]);
        glEnableClientState(GL_COLOR_ARRAY);
        glFeedbackBuffer(64, GL_3D_COLOR, buf);
        glRenderMode(GL_FEEDBACK);
        glDrawArrays(GL_POINTS, 0, N);
        n = glRenderMode(GL_RENDER);
        printf("%s_colors count %d\n", names[t], (int)n);
        for (i = 0; i < N && n == N * 8; i++) {
            for (c = 0; c < 4; c++) {
                double raw = t == 0 ? bytes[4 * i + c] : t == 1 ? shorts[4 * i + c]
                                                                : ints[4 * i + c];
                value[c] = clamp01(signed_to_float(raw, bits[t]));
            }
            printf("%s_color_%d", names[t], i);
            ffl_pfv("rgba", buf + 8 * i + 4, 4);
            printf(" ref");
            ffl_pdv("rgba", value, 4);
            printf("\n");
        }
        glDisableClientState(GL_COLOR_ARRAY);

        glNormalPointer(types[t], 4 * (t == 0 ? 1 : t == 1 ? 2 : 4), data[t]);
        glEnableClientState(GL_NORMAL_ARRAY);
        for (i = 0; i < N; i++) {
            GLfloat normal[3];
            glArrayElement(i);
            glGetFloatv(GL_CURRENT_NORMAL, normal);
            for (c = 0; c < 3; c++) {
                double raw = t == 0 ? bytes[4 * i + c] : t == 1 ? shorts[4 * i + c]
                                                                : ints[4 * i + c];
                value[c] = signed_to_float(raw, bits[t]);
            }
            printf("%s_normal_%d", names[t], i);
            ffl_pfv("normal", normal, 3);
            printf(" ref");
            ffl_pdv("normal", value, 3);
            printf("\n");
        }
        glDisableClientState(GL_NORMAL_ARRAY);
    }
    printf("error %s\n", ffl_error_name(glGetError()));
    return 0;
}
