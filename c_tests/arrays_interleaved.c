/* ffl-test: differential */
/*
 * glInterleavedArrays (§2.8, table 2.5) in all 14 formats, packed (stride 0)
 * and with an explicit stride: which arrays it enables (it disables the edge
 * flag array), each array's size, type, stride and pointer (printed as an
 * offset from the buffer), and the lit vertices drawn from it into feedback.
 * A NULL pointer is not used: fflight keeps every pointer NULL then (it has no
 * buffer objects to offset into), where GL would store the small offsets.
 */
#include "ffl_test.h"
#include <string.h>

#define COUNT 6
#define RECORD 64 /* bytes per vertex, more than any format needs */
#define FEEDBACK 4096

static const struct {
    GLenum format;
    const char *name;
    int size; /* tightly packed */
} formats[14] = {
    { GL_V2F, "v2f", 8 },
    { GL_V3F, "v3f", 12 },
    { GL_C4UB_V2F, "c4ub_v2f", 12 },
    { GL_C4UB_V3F, "c4ub_v3f", 16 },
    { GL_C3F_V3F, "c3f_v3f", 24 },
    { GL_N3F_V3F, "n3f_v3f", 24 },
    { GL_C4F_N3F_V3F, "c4f_n3f_v3f", 40 },
    { GL_T2F_V3F, "t2f_v3f", 20 },
    { GL_T4F_V4F, "t4f_v4f", 32 },
    { GL_T2F_C4UB_V3F, "t2f_c4ub_v3f", 24 },
    { GL_T2F_C3F_V3F, "t2f_c3f_v3f", 32 },
    { GL_T2F_N3F_V3F, "t2f_n3f_v3f", 32 },
    { GL_T2F_C4F_N3F_V3F, "t2f_c4f_n3f_v3f", 48 },
    { GL_T4F_C4F_N3F_V4F, "t4f_c4f_n3f_v4f", 60 },
};

static GLubyte data[COUNT * RECORD + 64];

/* Fills the buffer with values that read well as floats and as unsigned bytes
 * wherever a format puts them: each 4-byte word is a float in [0.25, 1.25)
 * with w words (the last float of a 4-component vertex) exactly 1 (OSMesa
 * lights w != 1 differently). Floats in that range have varied low bytes, so
 * the GL_C4UB formats read varied colors. */
static void fill(ffl_rng *rng, int stride, int vertex_offset_of_w)
{
    int i, w;
    for (i = 0; i < COUNT * RECORD + 64; i += 4) {
        GLfloat f = ffl_rng_float(rng, 0.25, 1.25);
        memcpy(data + i, &f, 4);
    }
    if (vertex_offset_of_w >= 0)
        for (w = 0; w < COUNT; w++) {
            GLfloat one = 1.0f;
            memcpy(data + w * stride + vertex_offset_of_w, &one, 4);
        }
}

static void print_array(const char *name, GLenum enabled, GLenum size, GLenum type, GLenum stride,
                        GLenum pointer)
{
    GLint v;
    GLvoid *p = NULL;
    printf("  %s enabled %d", name, (int)glIsEnabled(enabled));
    if (glIsEnabled(enabled)) {
        if (size) {
            glGetIntegerv(size, &v);
            printf(" size %d", (int)v);
        }
        glGetIntegerv(type, &v);
        printf(" type 0x%x", (unsigned)v);
        glGetIntegerv(stride, &v);
        printf(" stride %d", (int)v);
        glGetPointerv(pointer, &p);
        printf(" offset %ld", (long)((GLubyte *)p - data));
    }
    printf("\n");
}

int main(void)
{
    static const GLfloat light[4] = { 0.3f, 0.4f, 1.0f, 0.0f };
    static GLfloat buf[FEEDBACK];
    static const GLboolean flags[COUNT] = { 0 };
    ffl_rng rng;
    int f, explicit_stride, failed = 0;

    ffl_test_init();
    ffl_rng_seed(&rng, 99);
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 50);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(-0.7f, -0.7f, -5);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glEnable(GL_COLOR_MATERIAL);

    for (f = 0; f < 14; f++)
        for (explicit_stride = 0; explicit_stride <= 1; explicit_stride++) {
            int stride = formats[f].size + (explicit_stride ? 12 : 0);
            int w_offset = formats[f].format == GL_T4F_V4F ? 28
                           : formats[f].format == GL_T4F_C4F_N3F_V4F ? 56 : -1;
            char label[64];
            GLint n;
            fill(&rng, stride, w_offset);
            glEdgeFlagPointer(0, flags);
            glEnableClientState(GL_EDGE_FLAG_ARRAY);
            glInterleavedArrays(formats[f].format, explicit_stride ? stride : 0, data);
            printf("%s stride %d error %s\n", formats[f].name, explicit_stride ? stride : 0,
                   ffl_error_name(glGetError()));
            print_array("texcoord", GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_SIZE,
                        GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
                        GL_TEXTURE_COORD_ARRAY_POINTER);
            print_array("color", GL_COLOR_ARRAY, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE,
                        GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY_POINTER);
            print_array("normal", GL_NORMAL_ARRAY, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
                        GL_NORMAL_ARRAY_POINTER);
            print_array("vertex", GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE,
                        GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY_POINTER);
            printf("  edgeflag enabled %d\n", (int)glIsEnabled(GL_EDGE_FLAG_ARRAY));

            glFeedbackBuffer(FEEDBACK, GL_4D_COLOR_TEXTURE, buf);
            glRenderMode(GL_FEEDBACK);
            glDrawArrays(f % 2 ? GL_TRIANGLE_STRIP : GL_POINTS, 0, COUNT);
            n = glRenderMode(GL_RENDER);
            sprintf(label, "%s_%s", formats[f].name, explicit_stride ? "strided" : "packed");
            printf("%s count %d\n", label, (int)n);
            if (n < 0)
                failed = 1;
            else
                failed |= ffl_print_feedback(label, buf, n, GL_4D_COLOR_TEXTURE);
        }
    printf("error %s\n", ffl_error_name(glGetError()));
    return failed;
}
