/* Custom mutator of the VTU target (fuzz_vtu_mut; tests/fuzz/README.md). VTK reads its
 * sizes and layouts from XML attributes, which a byte mutator seldom rewrites whole, so
 * three times in four this one finds the input's NAME="VALUE" attributes loosely (no XML
 * parse) and edits one: a count or offset (NumberOfPoints, NumberOfComponents, offset...)
 * becomes an extreme, NaN-ish, huge, negative or nearby number; format, type, header_type,
 * byte_order, compressor, encoding and version take another valid or an invalid value;
 * once in eight the attribute is renamed to another known one. A number in the text
 * between tags (ascii arrays) is edited likewise. Otherwise, or when the input has
 * neither, libFuzzer's own mutator (LLVMFuzzerMutate) runs. Compiled without coverage
 * instrumentation, so its code adds no features of its own. */
#include "mutate_util.h"

typedef struct {
    size_t name, name_len, at, len;
} span; /* name_len 0: a number in text */

static const char *const names[] = {
    "NumberOfPoints", "NumberOfCells", "NumberOfComponents", "NumberOfTuples", "offset",  "format",   "type",    "Name",
    "header_type",    "byte_order",    "compressor",         "encoding",       "version", "RangeMin", "RangeMax"};
/* the values to try per attribute; a name not listed gets a number or an odd string */
static const struct {
    const char *name;
    const char *values[20];
} choices[] = {
    {"format", {"ascii", "binary", "appended", "Ascii", "xml", ""}},
    {"type",
     {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64", "Float32", "Float64", "String", "Bit",
      "IdType", "UnstructuredGrid", "PolyData", "ImageData", "PUnstructuredGrid", ""}},
    {"header_type", {"UInt32", "UInt64", "Int32", "Int64", "UInt8", ""}},
    {"byte_order", {"LittleEndian", "BigEndian", "Little", ""}},
    {"compressor", {"vtkZLibDataCompressor", "vtkLZ4DataCompressor", "vtkLZMADataCompressor", "vtkNoCompressor", ""}},
    {"encoding", {"raw", "base64", "ascii", ""}},
    {"version", {"0.1", "1.0", "2.2", "0.0", "99.9", "1", "-1"}},
};

static int name_char(uint8_t c)
{
    return (c | 0x20) >= 'a' && (c | 0x20) <= 'z' ? 1 : (c >= '0' && c <= '9') || c == '_' || c == ':' || c == '-';
}
static int digit(uint8_t c) { return c >= '0' && c <= '9'; }

/* The attributes (inside a tag) and the numbers of the text between tags, at most cap */
static size_t scan(const uint8_t *d, size_t size, span *t, size_t cap)
{
    size_t n = 0;
    int in_tag = 0;
    for (size_t i = 0; i < size && n < cap; i++) {
        if (d[i] == '<' || d[i] == '>') {
            in_tag = d[i] == '<';
            continue;
        }
        if (in_tag && (d[i] == '"' || d[i] == '\'') && i >= 2 && d[i - 1] == '=' && name_char(d[i - 2])) {
            size_t b = i - 1, e = i + 1;
            while (b > 0 && name_char(d[b - 1])) b--;
            while (e < size && d[e] != d[i]) e++;
            if (e == size) break;
            t[n++] = (span){b, i - 1 - b, i + 1, e - i - 1};
            i = e;
        } else if (!in_tag && (digit(d[i]) || (d[i] == '-' && i + 1 < size && digit(d[i + 1])))) {
            size_t e = i + 1;
            while (e < size && (digit(d[e]) || d[e] == '.' || d[e] == 'e' || d[e] == 'E' || d[e] == '-' || d[e] == '+'))
                e++;
            t[n++] = (span){0, 0, i, e - i};
            i = e - 1;
        }
    }
    return n;
}

/* A new value for the attribute named d[name, name + len) (into rep, cap >= 2048) */
static void value_for(unsigned *s, const uint8_t *d, const span *a, char *rep, size_t cap)
{
    for (size_t c = 0; a->name_len && c < sizeof choices / sizeof *choices; c++) {
        if (strlen(choices[c].name) != a->name_len || memcmp(choices[c].name, d + a->name, a->name_len)) continue;
        unsigned k = 0;
        while (k < 20 && choices[c].values[k]) k++;
        snprintf(rep, cap, "%s", mu_below(s, 8) ? choices[c].values[mu_below(s, k)] : "junk");
        return;
    }
    int text = a->name_len == 4 && !memcmp(d + a->name, "Name", 4);
    if (text && mu_below(s, 4)) mu_string(s, rep, cap);
    else mu_number(s, d + a->at, a->len, rep, cap);
}

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned seed)
{
    static span found[4096];
    static char rep[2048];
    unsigned s = seed;
    size_t n = mu_below(&s, 4) ? scan(data, size, found, sizeof found / sizeof *found) : 0;
    if (n == 0) return LLVMFuzzerMutate(data, size, max_size);
    span a = found[mu_below(&s, (unsigned)n)];
    size_t r;
    if (a.name_len && mu_below(&s, 8) == 0) { /* rename the attribute */
        const char *to = MU_PICK(&s, names);
        r = mu_splice(data, size, max_size, a.name, a.name_len, to, strlen(to));
    } else {
        value_for(&s, data, &a, rep, sizeof rep);
        r = mu_splice(data, size, max_size, a.at, a.len, rep, strlen(rep));
    }
    return r ? r : LLVMFuzzerMutate(data, size, max_size);
}
