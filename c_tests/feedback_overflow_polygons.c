/* ffl-test: differential */
/*
 * Feedback buffer overflow with segments and polygons (§5.3): when the
 * values do not fit, glRenderMode returns -1 and nothing is written past the
 * buffer's end (a guard region after it stays untouched); the values that
 * fit are written, in order. Buffers ending on a token, on a polygon's vertex
 * count, inside a vertex, between two vertices, exactly at the end of the
 * data and one value after it; in GL_3D_COLOR and GL_4D_COLOR_TEXTURE. Then
 * an ordinary pass: an overflow leaves nothing behind.
 *
 * The data (GL_3D_COLOR, 115 values): a pass-through (2 values), then for
 * each primitive a glPassThrough marker (2) and a GL_LINES segment
 * (1 + 2 x 7 = 15), a triangle (2 + 3 x 7 = 23) and a quad crossing the
 * right side of the view, fed back as a fan of three triangles (69). The values written are printed
 * raw, except the segment's token, printed as "segment_token": GL_LINES
 * gives GL_LINE_RESET_TOKEN by the spec and GL_LINE_TOKEN in OSMesa, a known
 * difference checked (with the rest of the stream, parsed) where the buffer
 * did not overflow.
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"

#define GUARD 64
#define SENTINEL -4242.0f
#define MAX_VALUES 512

static ffl_fb fb;

static void draw(void)
{
    glPassThrough(7.0f);
    ffl_fb_begin(&fb, GL_LINES);
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glVertex3f(-5, -5, 0);
    glColor4f(0.5f, 0.6f, 0.7f, 0.8f);
    glVertex3f(5, 4, 1);
    glEnd();
    ffl_fb_begin(&fb, GL_TRIANGLES);
    glColor4f(0.9f, 0.1f, 0.2f, 1.0f);
    glVertex3f(-3, -3, 0);
    glVertex3f(3, -3, 0);
    glColor4f(0.2f, 0.9f, 0.1f, 0.5f);
    glVertex3f(0, 4, 0);
    glEnd();
    ffl_fb_begin(&fb, GL_QUADS);
    glColor4f(0.3f, 0.3f, 0.9f, 1.0f);
    glVertex3f(-6, -2, 0);
    glVertex3f(14, -2, 0); /* right of the view: clipped */
    glColor4f(0.9f, 0.9f, 0.3f, 1.0f);
    glVertex3f(14, 6, 0);
    glVertex3f(-6, 6, 0);
    glEnd();
}

/* Prints the values written, with the tokens as names (see the header). */
static void print_values(const char *tag, const GLfloat *buf, int n)
{
    int k;
    printf("%s values", tag);
    for (k = 0; k < n; k++) {
        if (buf[k] == (GLfloat)GL_LINE_TOKEN || buf[k] == (GLfloat)GL_LINE_RESET_TOKEN)
            printf(" segment_token");
        else
            ffl_pf(buf[k]);
    }
    printf("\n");
}

static int run(GLenum type, const char *name, GLsizei size)
{
    static GLfloat buf[MAX_VALUES + GUARD];
    char tag[64];
    GLint n;
    int k, guard_ok = 1, untouched = 0;
    for (k = 0; k < MAX_VALUES + GUARD; k++)
        buf[k] = SENTINEL;
    sprintf(tag, "%s_size_%d", name, (int)size);
    ffl_fb_init(&fb);
    ffl_fb_start(&fb, buf, size, type);
    draw();
    n = glRenderMode(GL_RENDER);
    for (k = size; k < MAX_VALUES + GUARD; k++)
        if (buf[k] != SENTINEL)
            guard_ok = 0;
    for (k = 0; k < size; k++)
        if (buf[k] == SENTINEL)
            untouched++;
    printf("%s return %d guard_intact %d untouched_in_buffer %d error %s\n", tag, (int)n,
           guard_ok, untouched, ffl_error_name(glGetError()));
    print_values(tag, buf, size - untouched);
    if (n >= 0)
        ffl_print_feedback_prims(tag, buf, n, type, fb.modes, fb.nprims, NULL, NULL, NULL);
    return guard_ok ? 0 : 1;
}

int main(void)
{
    /* GL_3D_COLOR: pass 0-1 | marker 2-3 | segment token 4, vertices 5-11,
     * 12-18 | marker 19-20 | polygon token 21, count 22, vertices 23-43 |
     * marker 44-45 | three triangles 46-114 */
    static const GLsizei sizes_3d[] = { 1, 2, 3, 4, 5, 6, 12, 18, 19, 21, 22, 23, 24, 30,
                                        44, 46, 47, 48, 69, 70, 92, 113, 500 };
    static const GLsizei sizes_4d[] = { 3, 5, 12, 17, 18, 25, 29, 30, 31, 60, 100, 500 };
    int i, total, failed = 0;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -10, 10, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    for (i = 0; i < (int)(sizeof sizes_3d / sizeof sizes_3d[0]); i++)
        failed |= run(GL_3D_COLOR, "3d_color", sizes_3d[i]);
    for (i = 0; i < (int)(sizeof sizes_4d / sizeof sizes_4d[0]); i++)
        failed |= run(GL_4D_COLOR_TEXTURE, "4d_color_texture", sizes_4d[i]);

    /* the exact size of the whole data, and one less */
    {
        static GLfloat buf[MAX_VALUES];
        ffl_fb_init(&fb);
        ffl_fb_start(&fb, buf, MAX_VALUES, GL_3D_COLOR);
        draw();
        total = glRenderMode(GL_RENDER);
        printf("total %d\n", total);
    }
    failed |= run(GL_3D_COLOR, "3d_color_exact", (GLsizei)total);
    failed |= run(GL_3D_COLOR, "3d_color_one_short", (GLsizei)total - 1);
    failed |= run(GL_3D_COLOR, "3d_color_after", 500);
    return failed;
}
