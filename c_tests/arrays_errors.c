/* ffl-test: differential */
/*
 * Vertex array errors (§2.8, in Mesa's order of checks) and state (table
 * 6.8): the initial sizes, types, strides, enables and pointers; a bad size is
 * GL_INVALID_VALUE, a bad type GL_INVALID_ENUM, a negative stride
 * GL_INVALID_VALUE and is checked first, then the type, then the size; a
 * pointer command failing on its type or size changes nothing; bad client-state names and
 * interleaved formats are GL_INVALID_ENUM; a negative count is
 * GL_INVALID_VALUE, checked before the mode (GL_INVALID_ENUM) and the index
 * type (GL_INVALID_ENUM); glDrawRangeElements with end < start is
 * GL_INVALID_VALUE before anything else; glEnable accepts the client-state
 * arrays as Mesa does. Count 0 draws nothing and is no error.
 *
 * Not here: draws between glBegin and glEnd (OSMesa reports the error at
 * glEnd, fflight at the draw), a negative first element (fflight:
 * GL_INVALID_VALUE, OSMesa: nothing), glArrayElement(-1) (OSMesa crashes).
 */
#include "ffl_test.h"

static const GLfloat data[64] = { 0 };

static void print_state(const char *what)
{
    static const struct {
        GLenum pname;
        const char *name;
    } ints[] = {
        { GL_VERTEX_ARRAY_SIZE, "vertex_size" },
        { GL_VERTEX_ARRAY_TYPE, "vertex_type" },
        { GL_VERTEX_ARRAY_STRIDE, "vertex_stride" },
        { GL_NORMAL_ARRAY_TYPE, "normal_type" },
        { GL_NORMAL_ARRAY_STRIDE, "normal_stride" },
        { GL_COLOR_ARRAY_SIZE, "color_size" },
        { GL_COLOR_ARRAY_TYPE, "color_type" },
        { GL_COLOR_ARRAY_STRIDE, "color_stride" },
        { GL_TEXTURE_COORD_ARRAY_SIZE, "texcoord_size" },
        { GL_TEXTURE_COORD_ARRAY_TYPE, "texcoord_type" },
        { GL_TEXTURE_COORD_ARRAY_STRIDE, "texcoord_stride" },
        { GL_EDGE_FLAG_ARRAY_STRIDE, "edgeflag_stride" },
    };
    static const struct {
        GLenum array;
        const char *name;
    } enables[] = {
        { GL_VERTEX_ARRAY, "vertex_array" },
        { GL_NORMAL_ARRAY, "normal_array" },
        { GL_COLOR_ARRAY, "color_array" },
        { GL_INDEX_ARRAY, "index_array" },
        { GL_TEXTURE_COORD_ARRAY, "texcoord_array" },
        { GL_EDGE_FLAG_ARRAY, "edgeflag_array" },
    };
    static const struct {
        GLenum pname;
        const char *name;
    } pointers[] = {
        { GL_VERTEX_ARRAY_POINTER, "vertex_pointer" },
        { GL_NORMAL_ARRAY_POINTER, "normal_pointer" },
        { GL_COLOR_ARRAY_POINTER, "color_pointer" },
        { GL_TEXTURE_COORD_ARRAY_POINTER, "texcoord_pointer" },
        { GL_EDGE_FLAG_ARRAY_POINTER, "edgeflag_pointer" },
    };
    size_t k;
    printf("%s", what);
    for (k = 0; k < sizeof ints / sizeof ints[0]; k++) {
        GLint v = -1;
        glGetIntegerv(ints[k].pname, &v);
        printf(" %s 0x%x", ints[k].name, (unsigned)v);
    }
    for (k = 0; k < sizeof enables / sizeof enables[0]; k++) {
        GLboolean b = 9;
        glGetBooleanv(enables[k].array, &b);
        printf(" %s %d/%d", enables[k].name, (int)glIsEnabled(enables[k].array), (int)b);
    }
    for (k = 0; k < sizeof pointers / sizeof pointers[0]; k++) {
        GLvoid *p = (GLvoid *)&p;
        glGetPointerv(pointers[k].pname, &p);
        printf(" %s %s", pointers[k].name,
               p == NULL ? "null" : (const GLfloat *)p >= data && (const GLfloat *)p < data + 64
                   ? "data" : "other");
    }
    printf(" error %s\n", ffl_error_name(glGetError()));
}

#define CHECK(call) do { call; printf("%-60s %s\n", #call, ffl_error_name(glGetError())); } while (0)

int main(void)
{
    static const GLubyte indices[3] = { 0, 1, 2 };
    GLvoid *p;

    ffl_test_init();
    print_state("initial");

    glVertexPointer(3, GL_SHORT, 6, data);
    glNormalPointer(GL_BYTE, 3, data);
    glColorPointer(3, GL_UNSIGNED_SHORT, 8, data);
    glTexCoordPointer(1, GL_DOUBLE, 16, data);
    glEdgeFlagPointer(2, data);
    print_state("set");

    /* A negative stride alone: GL_INVALID_VALUE (OSMesa still stores the
     * call: see arrays_osmesa_diff_negative_stride.c), so the pointers are set
     * again after these. */
    CHECK(glVertexPointer(3, GL_FLOAT, -1, data));
    CHECK(glNormalPointer(GL_BYTE, -3, data));
    CHECK(glColorPointer(4, GL_FLOAT, -8, data));
    CHECK(glTexCoordPointer(2, GL_FLOAT, -4, data));
    CHECK(glEdgeFlagPointer(-1, data));
    glVertexPointer(3, GL_SHORT, 6, data);
    glNormalPointer(GL_BYTE, 3, data);
    glColorPointer(3, GL_UNSIGNED_SHORT, 8, data);
    glTexCoordPointer(1, GL_DOUBLE, 16, data);
    glEdgeFlagPointer(2, data);

    CHECK(glVertexPointer(1, GL_FLOAT, 0, data));
    CHECK(glVertexPointer(5, GL_FLOAT, 0, data));
    CHECK(glVertexPointer(3, GL_BYTE, 0, data));
    CHECK(glVertexPointer(3, GL_UNSIGNED_SHORT, 0, data));
    CHECK(glVertexPointer(5, GL_BYTE, -1, data));
    CHECK(glVertexPointer(5, GL_BYTE, 0, data));
    CHECK(glNormalPointer(GL_UNSIGNED_BYTE, 0, data));
    CHECK(glNormalPointer(GL_UNSIGNED_INT, 0, data));
    CHECK(glNormalPointer(GL_UNSIGNED_BYTE, -3, data));
    CHECK(glColorPointer(2, GL_FLOAT, 0, data));
    CHECK(glColorPointer(5, GL_FLOAT, 0, data));
    CHECK(glColorPointer(4, 0x1234, 0, data));
    CHECK(glColorPointer(2, GL_FLOAT, -8, data));
    CHECK(glTexCoordPointer(0, GL_FLOAT, 0, data));
    CHECK(glTexCoordPointer(5, GL_FLOAT, 0, data));
    CHECK(glTexCoordPointer(2, GL_BYTE, 0, data));
    CHECK(glTexCoordPointer(2, GL_UNSIGNED_INT, 0, data));
    print_state("after_pointer_errors");

    CHECK(glEnableClientState(GL_LIGHTING));
    CHECK(glDisableClientState(0x1234));
    CHECK(glEnableClientState(GL_VERTEX_ARRAY));
    CHECK(glEnableClientState(GL_INDEX_ARRAY));
    CHECK(glEnable(GL_COLOR_ARRAY));
    CHECK(glDisable(GL_INDEX_ARRAY));
    print_state("enables");
    CHECK(glDisable(GL_COLOR_ARRAY));

    CHECK(glInterleavedArrays(0x1234, 0, data));
    CHECK(glInterleavedArrays(0x1234, -1, data));
    CHECK(glInterleavedArrays(GL_V3F, -1, data));
    CHECK(glInterleavedArrays(GL_N3F_V3F, 0, data));
    print_state("interleaved");

    CHECK(glDrawArrays(0x1234, 0, 3)); /* (GL_POLYGON + 1 is GL_LINES_ADJACENCY to Mesa) */
    CHECK(glDrawArrays(GL_POINTS, 0, -1));
    CHECK(glDrawArrays(99, 0, -1));
    CHECK(glDrawArrays(GL_TRIANGLES, 0, 0));
    CHECK(glDrawElements(GL_POINTS, 3, GL_FLOAT, indices));
    CHECK(glDrawElements(GL_POINTS, 3, GL_BYTE, indices));
    CHECK(glDrawElements(GL_POINTS, -1, GL_UNSIGNED_BYTE, indices));
    CHECK(glDrawElements(99, 3, GL_UNSIGNED_BYTE, indices));
    CHECK(glDrawElements(99, 3, GL_FLOAT, indices));
    CHECK(glDrawElements(99, -1, GL_FLOAT, indices));
    CHECK(glDrawElements(GL_POINTS, 0, GL_UNSIGNED_INT, indices));
    CHECK(glDrawRangeElements(GL_POINTS, 5, 1, 3, GL_UNSIGNED_BYTE, indices));
    CHECK(glDrawRangeElements(99, 5, 1, -1, GL_FLOAT, indices));
    CHECK(glDrawRangeElements(GL_POINTS, 0, 1, -1, GL_FLOAT, indices));
    CHECK(glDrawRangeElements(99, 0, 1, 3, GL_FLOAT, indices));
    CHECK(glDrawRangeElements(GL_POINTS, 0, 1, 3, GL_SHORT, indices));
    CHECK(glGetPointerv(GL_VERTEX_ARRAY_SIZE, &p));
    CHECK(glGetPointerv(0x1234, &p));
    print_state("final");
    return 0;
}
