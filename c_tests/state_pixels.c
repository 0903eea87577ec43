/* ffl-test: differential */
/*
 * Pixel storage modes, pixel transfer, pixel maps and zoom (§3.6, §4.3.2; tables 6.21-6.25):
 * initial values, values set and read back (glGetPixelMap in its three types), the errors
 * (after which the state must be unchanged) and GL_INVALID_OPERATION between glBegin and
 * glEnd.
 * Not tried: a non-power-of-two size for GL_PIXEL_MAP_I_TO_I, which GL 1.5 rejects and Mesa
 * accepts; glGetPixelMapuiv of GL_PIXEL_MAP_S_TO_S, where Mesa returns its floats' bits;
 * glPixelStoref of a boolean mode with 0 < |param| < 0.5 (see
 * osmesa_diff_buffers_and_factors.c).
 */
#include "ffl_test.h"

static const GLenum store_modes[16] = {
    GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT,
    GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT,
    GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT,
    GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT
};

static const GLenum transfer_modes[14] = {
    GL_MAP_COLOR, GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE, GL_RED_BIAS,
    GL_GREEN_SCALE, GL_GREEN_BIAS, GL_BLUE_SCALE, GL_BLUE_BIAS, GL_ALPHA_SCALE, GL_ALPHA_BIAS,
    GL_DEPTH_SCALE, GL_DEPTH_BIAS
};

static void print_pixel_state(const char *what)
{
    int i;
    printf("%s\n", what);
    for (i = 0; i < 16; i++) {
        printf(" store %d", i);
        ffl_print_ints("", store_modes[i], 1);
    }
    for (i = 0; i < 14; i++) {
        printf(" transfer %d", i);
        ffl_print_floats("", transfer_modes[i], 1);
    }
    ffl_print_floats(" zoom_x", GL_ZOOM_X, 1);
    ffl_print_floats(" zoom_y", GL_ZOOM_Y, 1);
    for (i = 0; i < 10; i++) {
        printf(" map_size %d", i);
        ffl_print_ints("", GL_PIXEL_MAP_I_TO_I_SIZE + i, 1);
    }
}

/* Prints a map in the three types glGetPixelMap has. */
static void print_map(const char *what, GLenum map, int n)
{
    GLfloat f[16];
    GLuint ui[16];
    GLushort us[16];
    int i;
    glGetPixelMapfv(map, f);
    glGetPixelMapuiv(map, ui);
    glGetPixelMapusv(map, us);
    printf("%s", what);
    ffl_pfv("f", f, n);
    printf(" ui");
    for (i = 0; i < n; i++)
        printf(" %u", ui[i]);
    printf(" us");
    for (i = 0; i < n; i++)
        printf(" %u", (unsigned)us[i]);
    printf("\n");
}

int main(void)
{
    static const GLfloat colors[4] = { -0.5f, 0.25f, 0.75f, 2.0f };
    static const GLuint uints[2] = { 0u, 4294967295u };
    static const GLushort ushorts[4] = { 0, 1000, 65535, 32768 };
    static const GLfloat indices[2] = { 3.0f, 700.0f };
    static const GLuint stencils[2] = { 5u, 9u };
    GLint i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);

    ffl_print_ints("max_pixel_map_table", GL_MAX_PIXEL_MAP_TABLE, 1);
    print_pixel_state("initial");
    for (i = 0; i < 10; i++) {
        printf("map_initial %d", i);
        print_map("", GL_PIXEL_MAP_I_TO_I + i, 1);
    }
    ffl_print_error("initial_queries");

    for (i = 0; i < 16; i++)
        glPixelStorei(store_modes[i], i % 8 == 7 ? 1 << (i / 8 + 1) : i + 1);
    glPixelStoref(GL_PACK_ROW_LENGTH, 12.75f);
    glPixelStoref(GL_UNPACK_SWAP_BYTES, 0.0f);
    for (i = 0; i < 14; i++)
        glPixelTransferf(transfer_modes[i], (GLfloat)i - 3.25f);
    glPixelTransferi(GL_INDEX_OFFSET, -7);
    glPixelTransferf(GL_INDEX_SHIFT, 2.0f);
    glPixelZoom(2.0f, -0.5f);
    print_pixel_state("set");
    ffl_print_error("sets");

    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, colors);
    print_map("map_r_to_r_floats", GL_PIXEL_MAP_R_TO_R, 4);
    glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 2, uints);
    print_map("map_i_to_g_uints", GL_PIXEL_MAP_I_TO_G, 2);
    glPixelMapusv(GL_PIXEL_MAP_A_TO_A, 4, ushorts);
    print_map("map_a_to_a_ushorts", GL_PIXEL_MAP_A_TO_A, 4);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 2, indices);
    ffl_print_ints("map_i_to_i_size", GL_PIXEL_MAP_I_TO_I_SIZE, 1);
    glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, stencils);
    ffl_print_ints("map_s_to_s_size", GL_PIXEL_MAP_S_TO_S_SIZE, 1);
    ffl_print_error("maps");

    /* errors */
    glPixelStorei(GL_PACK_ALIGNMENT, 3);
    ffl_print_error("alignment_3");
    glPixelStorei(GL_UNPACK_ROW_LENGTH, -1);
    ffl_print_error("row_length_negative");
    glPixelStoref(GL_UNPACK_SKIP_PIXELS, -2.0f);
    ffl_print_error("skip_pixels_negative");
    glPixelStorei(GL_ZOOM_X, 1);
    ffl_print_error("store_bad_pname");
    glPixelTransferf(GL_ZOOM_Y, 1.0f);
    ffl_print_error("transfer_bad_pname");
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, colors);
    ffl_print_error("map_size_0");
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, colors);
    ffl_print_error("map_size_257");
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, colors);
    ffl_print_error("map_i_to_r_size_3");
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A + 1, 2, colors);
    ffl_print_error("map_bad_name");
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A + 1, -1, colors);
    ffl_print_error("map_bad_name_and_size");
    glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I - 1, NULL);
    ffl_print_error("get_map_bad_name");
    glBegin(GL_POINTS);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glEnd();
    ffl_print_error("store_inside_begin_end");
    glBegin(GL_POINTS);
    glPixelZoom(1.0f, 1.0f);
    glEnd();
    ffl_print_error("zoom_inside_begin_end");
    glBegin(GL_POINTS);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 1, colors);
    glEnd();
    ffl_print_error("map_inside_begin_end");
    print_pixel_state("after_errors");
    print_map("map_r_to_r_after_errors", GL_PIXEL_MAP_R_TO_R, 4);
    ffl_print_error("end");
    return 0;
}
