/* ffl-test: differential */
/*
 * Buffer objects (GL 1.5 §2.9): names, binding, data stores, mapping, the
 * parameters of table 2.6 and the errors of each command (in Mesa's order);
 * vertex arrays sourced from buffers (§2.9.1), mixed with client memory,
 * through glDrawArrays, glDrawElements with indices in an element array
 * buffer (§2.9.2), glDrawRangeElements, glArrayElement and
 * glInterleavedArrays at offset 0; data replaced by glBufferSubData and
 * through glMapBuffer; deleting a bound buffer resets the bindings. Every
 * draw is fed back and compared across builds.
 *
 * osmesa-known: line-reset
 */
#include "ffl_test.h"

#define COUNT 10
#define FEEDBACK 4096

static GLfloat feedback[FEEDBACK];
static ffl_fb fb;

static void start(GLenum mode)
{
    ffl_fb_draw_start(&fb, feedback, FEEDBACK, GL_3D_COLOR, mode);
}

static int finish(const char *label)
{
    return ffl_fb_draw_finish(&fb, label);
}

static void error(const char *what)
{
    printf("%s error %s\n", what, ffl_error_name(glGetError()));
}

static void parameters(const char *what, GLenum target)
{
    GLint size = -1, usage = -1, access = -1, mapped = -1;
    glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
    glGetBufferParameteriv(target, GL_BUFFER_USAGE, &usage);
    glGetBufferParameteriv(target, GL_BUFFER_ACCESS, &access);
    glGetBufferParameteriv(target, GL_BUFFER_MAPPED, &mapped);
    printf("%s size %d usage 0x%x access 0x%x mapped %d", what, size, usage, access, mapped);
    error("");
}

static void bindings(const char *what)
{
    static const GLenum names[7] = {
        GL_ARRAY_BUFFER_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING,
        GL_VERTEX_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_BUFFER_BINDING,
        GL_COLOR_ARRAY_BUFFER_BINDING, GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
        GL_EDGE_FLAG_ARRAY_BUFFER_BINDING
    };
    int i;
    printf("%s bindings", what);
    for (i = 0; i < 7; i++) {
        GLint value = -1;
        glGetIntegerv(names[i], &value);
        printf(" %d", value);
    }
    error("");
}

int main(void)
{
    /* Interleaved: position (3 floats), normal (3 floats). */
    static GLfloat vertices[COUNT][6];
    static GLubyte colors[COUNT][4];
    static const GLushort indices[12] = { 0, 1, 2, 2, 3, 4, 9, 8, 7, 5, 6, 1 };
    static const GLfloat light[4] = { 0.3f, 0.5f, 1.0f, 0.0f };
    GLuint names[4], after[2];
    GLfloat read_back[4] = { 0, 0, 0, 0 };
    GLfloat *mapped;
    void *pointer = NULL;
    ffl_rng rng;
    int failed = 0, i;

    ffl_test_init();
    ffl_rng_seed(&rng, 11);
    for (i = 0; i < COUNT; i++) {
        double angle = 2 * FFL_PI * i / COUNT;
        vertices[i][0] = (GLfloat)(2.0 * cos(angle));
        vertices[i][1] = (GLfloat)(1.5 * sin(angle));
        vertices[i][2] = (GLfloat)(0.2 * cos(angle));
        vertices[i][3] = ffl_rng_float(&rng, -0.5f, 0.5f);
        vertices[i][4] = ffl_rng_float(&rng, -0.5f, 0.5f);
        vertices[i][5] = 1.0f;
        colors[i][0] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][1] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][2] = (GLubyte)ffl_rng_int(&rng, 256);
        colors[i][3] = 255;
    }
    glViewport(0, 0, 64, 64);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 2, 50);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0, 0, -7);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_COLOR_MATERIAL);

    /* Names, binding and the errors of each command. */
    bindings("initial");
    glBufferData(GL_ARRAY_BUFFER, 16, vertices, GL_STATIC_DRAW);
    error("data_unbound");
    glBufferData(0x1234, -1, vertices, 0);
    error("data_bad_target");
    glGenBuffers(-1, names);
    error("gen_negative");
    glGenBuffers(4, names);
    printf("names %u %u %u %u is %d", names[0], names[1], names[2], names[3],
           (int)glIsBuffer(names[0]));
    error("");
    glBindBuffer(0x1234, names[0]);
    error("bind_bad_target");
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    printf("bound is %d", (int)glIsBuffer(names[0]));
    error("");
    parameters("new", GL_ARRAY_BUFFER);
    glBufferData(GL_ARRAY_BUFFER, -1, vertices, 0x1234);
    error("data_negative_bad_usage");
    glBufferData(GL_ARRAY_BUFFER, 16, vertices, 0x1234);
    error("data_bad_usage");
    glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_DYNAMIC_DRAW);
    parameters("data", GL_ARRAY_BUFFER);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, 0x1234, &i);
    error("parameter_bad_pname");
    glGetBufferParameteriv(0x1234, GL_BUFFER_SIZE, &i);
    error("parameter_bad_target");
    glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_SIZE, &i);
    error("parameter_unbound");
    glBufferSubData(GL_ARRAY_BUFFER, -1, 4, vertices);
    error("sub_negative_offset");
    glBufferSubData(GL_ARRAY_BUFFER, 4, -1, vertices);
    error("sub_negative_size");
    glBufferSubData(GL_ARRAY_BUFFER, (GLintptr)sizeof vertices - 4, 8, vertices);
    error("sub_past_end");
    glGetBufferSubData(GL_ARRAY_BUFFER, 4 * sizeof(GLfloat), sizeof read_back, read_back);
    ffl_pfv("read_back", read_back, 4);
    error("");
    glGetBufferSubData(GL_ARRAY_BUFFER, (GLintptr)sizeof vertices, 1, read_back);
    error("get_sub_past_end");

    /* Arrays in the buffer, colors in client memory. */
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(GLfloat), (const void *)0);
    glNormalPointer(GL_FLOAT, 6 * sizeof(GLfloat), (const void *)(3 * sizeof(GLfloat)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glGetPointerv(GL_NORMAL_ARRAY_POINTER, &pointer);
    printf("normal_offset %d", (int)(size_t)pointer);
    error("");
    bindings("arrays");

    start(GL_TRIANGLE_STRIP);
    glDrawArrays(GL_TRIANGLE_STRIP, 1, 8);
    failed |= finish("draw_arrays");

    /* Indices in an element array buffer, at an offset. */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, names[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof indices, indices, GL_STATIC_DRAW);
    bindings("elements");
    start(GL_TRIANGLES);
    glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, (const void *)(3 * sizeof(GLushort)));
    failed |= finish("draw_elements");
    start(GL_LINES);
    glDrawRangeElements(GL_LINES, 0, COUNT - 1, 12, GL_UNSIGNED_SHORT, (const void *)0);
    failed |= finish("draw_range_elements");
    start(GL_POINTS);
    glBegin(GL_POINTS);
    glArrayElement(7);
    glArrayElement(2);
    glEnd();
    failed |= finish("array_element");

    /* New data: a glBufferSubData, then writes through a mapping. */
    glBindBuffer(GL_ARRAY_BUFFER, names[0]);
    read_back[0] = 0.25f;
    read_back[1] = -0.5f;
    glBufferSubData(GL_ARRAY_BUFFER, 6 * sizeof(GLfloat), 2 * sizeof(GLfloat), read_back);
    mapped = (GLfloat *)glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    printf("mapped %d", mapped != NULL);
    error("");
    parameters("mapped", GL_ARRAY_BUFFER);
    glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &pointer);
    printf("map_pointer_matches %d", pointer == (void *)mapped);
    error("");
    glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    error("map_twice");
    glBufferSubData(GL_ARRAY_BUFFER, 0, 4, read_back);
    error("sub_while_mapped");
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, read_back);
    error("get_sub_while_mapped");
    if (mapped != NULL) {
        for (i = 0; i < COUNT; i++) {
            mapped[6 * i + 2] = (GLfloat)(0.1 * i - 0.4);
        }
    }
    printf("unmap %d", (int)glUnmapBuffer(GL_ARRAY_BUFFER));
    error("");
    printf("unmap_again %d", (int)glUnmapBuffer(GL_ARRAY_BUFFER));
    error("");
    glUnmapBuffer(0x1234);
    error("unmap_bad_target");
    glMapBuffer(GL_ARRAY_BUFFER, 0x1234);
    error("map_bad_access");
    parameters("unmapped", GL_ARRAY_BUFFER);
    start(GL_QUADS);
    glDrawArrays(GL_QUADS, 0, 8);
    failed |= finish("draw_after_map");

    /* glInterleavedArrays at offset 0 of the bound buffer. */
    glInterleavedArrays(GL_N3F_V3F, 0, (const void *)0);
    bindings("interleaved");
    start(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, 4);
    failed |= finish("interleaved");

    /* Deleting bound buffers resets every binding to them; names count up. */
    glDeleteBuffers(-1, names);
    error("delete_negative");
    glDeleteBuffers(2, names);
    printf("deleted is %d %d", (int)glIsBuffer(names[0]), (int)glIsBuffer(names[1]));
    error("");
    bindings("deleted");
    glGenBuffers(2, after);
    printf("after_delete names %u %u", after[0], after[1]);
    error("");
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY);
    error("map_unbound");
    glBindBuffer(GL_ARRAY_BUFFER, after[0]);
    glBufferData(GL_ARRAY_BUFFER, 0, NULL, GL_STREAM_COPY);
    parameters("empty", GL_ARRAY_BUFFER);
    glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
    error("map_empty");
    return failed;
}
