/* ffl-test: differential */
/*
 * Display list errors and state (§5.4, §6.1): glNewList with list 0, a bad
 * mode, inside a list, between glBegin and glEnd; glEndList without a list;
 * glGenLists and glDeleteLists with a negative range; glCallList(0);
 * glCallLists with a negative count or a bad type (even with a count of 0);
 * GL_LIST_INDEX, GL_LIST_MODE, GL_LIST_BASE; glIsList of a list being
 * compiled and of names glGenLists reserved. Errors of commands compiled in
 * GL_COMPILE mode are raised when the list executes, not at compile time;
 * under GL_COMPILE_AND_EXECUTE they are raised at once.
 */
#include "ffl_test.h"

static void get(const char *what)
{
    GLint index = -7, mode = -7, base = -7;
    glGetIntegerv(GL_LIST_INDEX, &index);
    glGetIntegerv(GL_LIST_MODE, &mode);
    glGetIntegerv(GL_LIST_BASE, &base);
    printf("%s index %d mode %d base %d\n", what, (int)index, (int)mode, (int)base);
}

int main(void)
{
    GLuint first;
    GLint name = 1;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    get("initial");
    glNewList(0, GL_COMPILE);
    ffl_print_error("new_list_0");
    glNewList(1, GL_RENDER);
    ffl_print_error("new_list_bad_mode");
    glEndList();
    ffl_print_error("end_list_without_list");
    glBegin(GL_POINTS);
    glNewList(1, GL_COMPILE);
    glEnd();
    ffl_print_error("new_list_in_begin");
    get("after_new_list_in_begin");

    glNewList(1, GL_COMPILE);
    ffl_print_error("new_list");
    get("compiling");
    printf("is_list_compiling %d\n", (int)glIsList(1));
    glNewList(2, GL_COMPILE);
    ffl_print_error("new_list_nested");
    get("after_nested");
    /* Compiled, not executed: no error now. */
    glLightf(GL_LIGHT0, GL_RENDER, 1.0f);
    glEnable(GL_RENDER);
    glBegin(GL_RENDER);
    glPopMatrix();
    glCallList(0);
    glCallLists(-1, GL_INT, &name);
    glCallLists(1, GL_DOUBLE, &name);
    glListBase(7);
    ffl_print_error("compiled_errors");
    get("compiled_list_base");
    glEndList();
    ffl_print_error("end_list");
    get("after_end_list");
    printf("is_list_compiled %d\n", (int)glIsList(1));

    glCallList(1);
    ffl_print_error("call_first_error");
    ffl_print_error("call_second_error");
    ffl_print_error("call_third_error");
    ffl_print_error("call_fourth_error");
    get("after_call");
    glListBase(0);

    glNewList(3, GL_COMPILE_AND_EXECUTE);
    glPopMatrix();
    ffl_print_error("compile_and_execute_now");
    glEndList();
    glCallList(3);
    ffl_print_error("compile_and_execute_call");

    glCallList(0);
    ffl_print_error("call_list_0");
    glCallList(12345);
    ffl_print_error("call_list_undefined");
    glCallLists(-1, GL_INT, &name);
    ffl_print_error("call_lists_negative");
    glCallLists(1, GL_DOUBLE, &name);
    ffl_print_error("call_lists_bad_type");
    glCallLists(0, GL_DOUBLE, &name);
    ffl_print_error("call_lists_none_bad_type");

    printf("gen_negative %u\n", glGenLists(-1));
    ffl_print_error("gen_lists_negative");
    printf("gen_zero %u\n", glGenLists(0));
    ffl_print_error("gen_lists_zero");
    first = glGenLists(3);
    printf("gen_three %u\n", first);
    printf("is_list %d %d %d %d\n", (int)glIsList(first), (int)glIsList(first + 1),
           (int)glIsList(first + 2), (int)glIsList(first + 3));
    glCallList(first);
    ffl_print_error("call_empty");
    glDeleteLists(first, -1);
    ffl_print_error("delete_negative");
    glDeleteLists(first, 0);
    ffl_print_error("delete_zero");
    printf("is_list_after_delete_zero %d\n", (int)glIsList(first));
    glDeleteLists(0, 3);
    ffl_print_error("delete_from_0");
    printf("is_list_1_after_delete %d\n", (int)glIsList(1));
    /* OSMesa visits every name of the range: 38 s for this one, so it gets a range that
     * ends at 2^26 (the same lists deleted), fflight the hostile one. */
#ifdef FFL_OSMESA
    glDeleteLists(first, (1 << 26) - (GLsizei)first);
#else
    glDeleteLists(first, 2000000000);
#endif
    ffl_print_error("delete_huge_range");
    printf("is_list_after_delete %d %d\n", (int)glIsList(first), (int)glIsList(first + 2));
    printf("is_list_0 %d\n", (int)glIsList(0));

    glBegin(GL_POINTS);
    glEndList();
    glEnd();
    ffl_print_error("end_list_in_begin");
    glBegin(GL_POINTS);
    glGenLists(1);
    glEnd();
    ffl_print_error("gen_lists_in_begin");
    glBegin(GL_POINTS);
    glDeleteLists(1, 1);
    glEnd();
    ffl_print_error("delete_lists_in_begin");
    glBegin(GL_POINTS);
    glIsList(1);
    glEnd();
    ffl_print_error("is_list_in_begin");
    glBegin(GL_POINTS);
    glListBase(1);
    glEnd();
    ffl_print_error("list_base_in_begin");
    glBegin(GL_POINTS);
    glCallList(first);
    glCallLists(1, GL_INT, &name);
    glEnd();
    ffl_print_error("call_in_begin");
    return 0;
}
