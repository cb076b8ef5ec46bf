/* Part of both extensions (_speedups.c and _lexer.c include it first): what each of their parts uses. */

/* Append a new reference to ``list`` and release it: -1 if making ``item`` failed (NULL) or the append did. */
static inline int append_new(PyObject *list, PyObject *item)
{
    int failed;
    if (item == NULL)
        return -1;
    failed = PyList_Append(list, item);
    Py_DECREF(item);
    return failed;
}

/* Interned strings of ``names`` into ``out``: -1 if one cannot be made. */
static inline int intern_all(PyObject **out, const char *const *names, size_t count)
{
    size_t k;
    for (k = 0; k < count; k++)
        if ((out[k] = PyUnicode_InternFromString(names[k])) == NULL)
            return -1;
    return 0;
}
