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

/* The UTF-8 bytes of ``text`` as Python's own str methods see its code points: a lone surrogate (a line
 * or a file name read with surrogateescape) is written as its three bytes ("surrogatepass") instead of
 * failing, so both cores read the same text.  ``*keep`` owns those bytes when it is not NULL (release it
 * with Py_XDECREF); NULL only with an error set. */
static inline const char *utf8_pass(PyObject *text, Py_ssize_t *len, PyObject **keep)
{
    const char *s = PyUnicode_AsUTF8AndSize(text, len);
    *keep = NULL;
    if (s != NULL || !PyErr_ExceptionMatches(PyExc_UnicodeEncodeError))
        return s;
    PyErr_Clear();
    if ((*keep = PyUnicode_AsEncodedString(text, "utf-8", "surrogatepass")) == NULL)
        return NULL;
    *len = PyBytes_Size(*keep);
    return PyBytes_AsString(*keep);
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
