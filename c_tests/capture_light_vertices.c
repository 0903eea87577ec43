/* ffl-test: fflight-only */
/*
 * fflLightVertices lights whole arrays with the current state, exactly as
 * immediate mode lights each vertex: its outputs are compared bit for bit
 * with the captured vertices of glBegin(GL_POINTS) / glColor4fv / glNormal3fv
 * / glVertex{2,3,4}fv / glEnd. Inputs packed and in an array of structs;
 * outputs into an array of structs (strides) and packed arrays; NULL normals
 * and colors (the current ones are used), NULL outputs (skipped). The current
 * attributes are left alone and nothing is captured or fed back. Errors.
 */
#include "ffl_test.h"
#include <string.h>

#define N 50

typedef struct {
    GLfloat eye[4], clip[4];
    GLfloat front_primary[4], front_secondary[4], back_primary[4], back_secondary[4];
} lit_vertex;

typedef struct {
    char tag;
    GLfloat position[4];
    GLfloat normal[3];
    GLfloat color[4];
} input_vertex;

static int failures = 0;

static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("FAILED %s\n", what);
        failures++;
    }
}

static void set_current(void)
{
    glColor4f(0.3f, 0.6f, 0.9f, 0.5f);
    glNormal3f(0.1f, -0.2f, 0.9f);
}

/* The captured immediate-mode result for the inputs, as lit_vertex. */
static void immediate(int size, const input_vertex *in, int normals, int colors, lit_vertex *out)
{
    static FflCapturedVertex captured[N];
    int i;
    set_current();
    fflCaptureBegin();
    glBegin(GL_POINTS);
    for (i = 0; i < N; i++) {
        if (colors)
            glColor4fv(in[i].color);
        if (normals)
            glNormal3fv(in[i].normal);
        if (size == 2)
            glVertex2fv(in[i].position);
        else if (size == 3)
            glVertex3fv(in[i].position);
        else
            glVertex4fv(in[i].position);
    }
    glEnd();
    fflCaptureEnd();
    set_current();
    expect(fflCaptureReadVertices(0, N, captured) == N, "captured");
    for (i = 0; i < N; i++) {
        memcpy(out[i].eye, captured[i].eye, sizeof out[i].eye);
        memcpy(out[i].clip, captured[i].clip, sizeof out[i].clip);
        memcpy(out[i].front_primary, captured[i].front_primary, 16);
        memcpy(out[i].front_secondary, captured[i].front_secondary, 16);
        memcpy(out[i].back_primary, captured[i].back_primary, 16);
        memcpy(out[i].back_secondary, captured[i].back_secondary, 16);
    }
}

int main(void)
{
    static const GLfloat light0[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    static const GLfloat light1[4] = { -2.0f, 1.0f, 3.0f, 1.0f };
    static const GLfloat spec[4] = { 0.8f, 0.8f, 0.8f, 1.0f };
    static input_vertex in[N];
    static GLfloat positions[N * 4], normals[N * 3], colors[N * 4];
    static lit_vertex expected[N], got[N + 1];
    static GLfloat packed[6][N * 4 + 4];
    GLfloat current_before[8], current_after[8];
    ffl_rng rng;
    int i, size, with_normals, with_colors, k;
    char what[96];

    ffl_test_init();
    ffl_rng_seed(&rng, 31);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.2f, -0.1f, -5);
    glRotatef(30, 1, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_POSITION, light0);
    glLightfv(GL_LIGHT1, GL_POSITION, light1);
    glLightfv(GL_LIGHT1, GL_SPECULAR, spec);
    glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.05f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);

    for (i = 0; i < N; i++) {
        in[i].tag = 'v';
        for (k = 0; k < 4; k++) {
            in[i].position[k] = k == 3 ? ffl_rng_float(&rng, 0.5, 2) : ffl_rng_float(&rng, -2, 2);
            in[i].color[k] = ffl_rng_float(&rng, -0.1, 1.1);
        }
        for (k = 0; k < 3; k++)
            in[i].normal[k] = ffl_rng_float(&rng, -1, 1);
        memcpy(normals + 3 * i, in[i].normal, sizeof in[i].normal);
        memcpy(colors + 4 * i, in[i].color, sizeof in[i].color);
    }

    for (size = 2; size <= 4; size++)
        for (with_normals = 0; with_normals <= 1; with_normals++)
            for (with_colors = 0; with_colors <= 1; with_colors++) {
                sprintf(what, "size %d normals %d colors %d", size, with_normals, with_colors);
                for (i = 0; i < N; i++)
                    memcpy(positions + size * i, in[i].position, (size_t)size * sizeof(GLfloat));
                immediate(size, in, with_normals, with_colors, expected);

                /* Packed inputs, outputs into an array of structs. */
                memset(got, 0x7f, sizeof got);
                glGetFloatv(GL_CURRENT_COLOR, current_before);
                glGetFloatv(GL_CURRENT_NORMAL, current_before + 4);
                fflCaptureBegin();
                fflLightVertices(N, size, positions, 0, with_normals ? normals : NULL, 0,
                                 with_colors ? colors : NULL, 0, got[0].eye, sizeof(lit_vertex),
                                 got[0].clip, sizeof(lit_vertex), got[0].front_primary,
                                 sizeof(lit_vertex), got[0].front_secondary, sizeof(lit_vertex),
                                 got[0].back_primary, sizeof(lit_vertex), got[0].back_secondary,
                                 sizeof(lit_vertex));
                fflCaptureEnd();
                glGetFloatv(GL_CURRENT_COLOR, current_after);
                glGetFloatv(GL_CURRENT_NORMAL, current_after + 4);
                expect(glGetError() == GL_NO_ERROR, what);
                expect(memcmp(got, expected, sizeof expected) == 0, what);
                expect(got[N].eye[0] != got[N].eye[0] || got[N].eye[0] > 1e38f, "nothing past N");
                expect(memcmp(current_before, current_after, 7 * sizeof(GLfloat)) == 0,
                       "current attributes unchanged");
                expect(fflCaptureVertexCount() == 0, "nothing captured");

                /* Inputs read from the array of structs (strides), packed
                 * outputs, two of them skipped. */
                memset(packed, 0, sizeof packed);
                fflLightVertices(N, size, in[0].position, sizeof(input_vertex),
                                 with_normals ? in[0].normal : NULL, sizeof(input_vertex),
                                 with_colors ? in[0].color : NULL, sizeof(input_vertex),
                                 packed[0], 0, NULL, 0, packed[2], 16, packed[3], 0, NULL, 0,
                                 packed[5], 0);
                expect(glGetError() == GL_NO_ERROR, what);
                for (i = 0; i < N; i++) {
                    expect(memcmp(packed[0] + 4 * i, expected[i].eye, 16) == 0, what);
                    expect(memcmp(packed[2] + 4 * i, expected[i].front_primary, 16) == 0, what);
                    expect(memcmp(packed[3] + 4 * i, expected[i].front_secondary, 16) == 0, what);
                    expect(memcmp(packed[5] + 4 * i, expected[i].back_secondary, 16) == 0, what);
                }
            }
    printf("compared %d configurations of %d vertices\n", 12, N);

    /* Errors: nothing is written. */
    memset(packed, 0, sizeof packed);
    fflLightVertices(-1, 3, positions, 0, NULL, 0, NULL, 0, packed[0], 0, NULL, 0, NULL, 0, NULL,
                     0, NULL, 0, NULL, 0);
    expect(glGetError() == GL_INVALID_VALUE, "negative count");
    fflLightVertices(N, 1, positions, 0, NULL, 0, NULL, 0, packed[0], 0, NULL, 0, NULL, 0, NULL,
                     0, NULL, 0, NULL, 0);
    expect(glGetError() == GL_INVALID_VALUE, "position size 1");
    fflLightVertices(N, 3, positions, -12, NULL, 0, NULL, 0, packed[0], 0, NULL, 0, NULL, 0,
                     NULL, 0, NULL, 0, NULL, 0);
    expect(glGetError() == GL_INVALID_VALUE, "negative stride");
    fflLightVertices(N, 3, NULL, 0, NULL, 0, NULL, 0, packed[0], 0, NULL, 0, NULL, 0, NULL, 0,
                     NULL, 0, NULL, 0);
    expect(glGetError() == GL_INVALID_VALUE, "NULL positions");
    glBegin(GL_POINTS);
    fflLightVertices(N, 3, positions, 0, NULL, 0, NULL, 0, packed[0], 0, NULL, 0, NULL, 0, NULL,
                     0, NULL, 0, NULL, 0);
    glEnd();
    expect(glGetError() == GL_INVALID_OPERATION, "between glBegin and glEnd");
    for (i = 0; i < N * 4; i++)
        expect(packed[0][i] == 0.0f, "nothing written on error");
    printf("failures %d\n", failures);
    return failures != 0;
}
