#line 374 "paper/scene.nw"
#ifndef CONTACTOPT_SCENE_PRIVATE_H
#define CONTACTOPT_SCENE_PRIVATE_H
/* The scene module's own header: the files scene*.c include it, no other
   module does. */
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include "scene.h"

#line 631 "paper/scene.nw"
typedef enum { KEY_REAL, KEY_INT, KEY_WORD, KEY_TEXT } Scene_key_type;
typedef const char *Scene_default_of(const char *key, int k, char *buf,
                               size_t size);
#define AT(field) ((long)offsetof(Scene, field))

typedef struct {
  const char *sec, *key;     /* the section and the key */
  Scene_key_type type;       /* a real, an integer, a word, a text */
  const char *const *words;  /* the words a word (or design.initial) takes */
  long at;                   /* the offset of its value in a Scene */
  const char *unit;          /* m, Pa, ...; 1: a pure number; -: none */
  const char *dflt;          /* the default as a scene writes it, or */
  Scene_default_of *by;      /* the default under the selector's word k */
  const char *selector;      /* a word of the section that decides: */
  const char *when;          /* its words with which the key means something,
                                blank-separated (NULL: all of them) */
  const char *accepted;      /* the values accepted (NULL: the words) */
  const char *meaning;       /* one line */
  int strain;                /* means something in plane strain only */
  int rectangle;             /* a key of the rectangle: none with a part */
  int quiet;                 /* written only where it is not its default */
} Scene_key;

_Static_assert(sizeof(Problem_plane_model) == sizeof(int)
               && sizeof(Problem_bc_kind) == sizeof(int)
               && sizeof(Problem_contact_law) == sizeof(int)
               && sizeof(Problem_material_kind) == sizeof(int)
               && sizeof(Qp_method) == sizeof(int)
               && sizeof(Opt_method) == sizeof(int)
               && sizeof(Opt_metric) == sizeof(int)
               && sizeof(Objective_kind) == sizeof(int),
               "a word of a scene is an enum stored as an int");
#line 417 "paper/scene.nw"
enum { SCENE_NKEYS = 80 };  /* the records of the table of keys */
extern const char *const scene_side_names[];    /* left, right, top */
extern const char *const scene_initial_names[]; /* arc, line, constant, file */
extern const char *const scene_material_kind_names[]; /* isotropic, ... */
extern const Scene_key scene_keys[SCENE_NKEYS]; /* the table of keys */
/* the named sections: [boundary.NAME], [material.NAME] */
enum { SCENE_BOUNDARY, SCENE_MATERIAL, SCENE_NAMED_KINDS };
typedef struct {
  const char *prefix;  /* boundary, material */
  const char *table;   /* the section of their records: boundary.NAME */
  size_t stride;       /* the bytes from one slot of problem.part to the next */
} Scene_named;
extern const Scene_named scene_named[SCENE_NAMED_KINDS];
/* the kind of the named section sec, or -1; *name = its NAME */
int scene_named_kind(const char *sec, const char **name);
/* inih keeps INIH_SECTION - 1 characters of a section name (its ini.c's
   MAX_SECTION); a NAME fits after the prefix boundary. or material. */
enum { INIH_SECTION = 50, SCENE_NAME_MAX = INIH_SECTION - 1 - 9 };
_Static_assert((int)SCENE_NAME_MAX < (int)PROBLEM_NAME, "a NAME fits its slot");
/* whether name is a NAME: [A-Za-z0-9_]+, at most SCENE_NAME_MAX */
int scene_name_ok(const char *name);
/* the section of the table that holds the keys of sec: sec, or PREFIX.NAME */
const char *scene_table_section(const char *sec);
/* the index of w in the NULL-terminated list names, or -1 */
int scene_name_index(const char *const *names, const char *w);
/* buf = the names, comma-separated (cut to size) */
const char *scene_name_list(const char *const *names, char *buf,
                            size_t size);
/* the record of sec.key, or NULL */
const Scene_key *scene_key_find(const char *sec, const char *key);
/* whether sec is a section of the table */
int scene_section_known(const char *sec);
/* buf = the sections (sec NULL) or the keys of sec, comma-separated */
const char *scene_key_names(const char *sec, char *buf, size_t size);
/* whether k means something when its selector has the word w */
int scene_key_means(const Scene_key *k, const char *w);
#line 982 "paper/scene.nw"
enum { ENTRY_VALUE = 256, NAMED_KEYS = 15,
       TABLE_MAX = SCENE_NKEYS - NAMED_KEYS + PROBLEM_NAMED * NAMED_KEYS };
_Static_assert((int)SCENE_NKEYS <= (int)TABLE_MAX,
               "a scene's values fit the loader");

typedef struct {
  char sec[PROBLEM_NAME + 16], key[16]; /* a section and a key of the table */
  char val[ENTRY_VALUE];  /* the value, without blanks around or comment */
  int line;               /* its line in the scene file; 0: -s or default */
  const char *override;   /* the -s string that set it, or NULL */
} Scene_entry;
#line 1000 "paper/scene.nw"
typedef struct {
  const char *path;      /* the scene file: the first word of every message */
  Status *st;            /* where a failure is told (may be NULL) */
  int failed;            /* 0, or the code of the failure told */
  Scene_entry e[TABLE_MAX]; /* the values given, in the order met */
  int n;                 /* entries used */
  FILE *fp;              /* the reader: the scene file, */
  int line;              /* the number of the line just read, 0 after it, */
  int indented;          /* whether that line starts with a blank, */
  const Scene_entry *prev; /* and the entry set by the previous key line */
  const char *override;  /* the override being applied, or NULL */
  Scene_entry last;      /* the value converted last: a check blames it */
} Scene_loader;
#line 1054 "paper/scene.nw"
#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif
#line 1038 "paper/scene.nw"
/* tell "fmt ..." as the failure of L, STATUS_INPUT */
PRINTF_LIKE(2, 3) int scene_fail(Scene_loader *L, const char *fmt, ...);
/* tell "ORIGIN: section.key = value: reason" about e */
PRINTF_LIKE(3, 4) int scene_bad(Scene_loader *L, const Scene_entry *e,
                                const char *fmt, ...);
/* the same about the value converted last, L->last */
PRINTF_LIKE(2, 3) int scene_blame(Scene_loader *L, const char *fmt, ...);
/* buf = the scene path, and the override if one set the value */
void scene_origin(const Scene_loader *L, const char *override, char *buf,
                  size_t size);
#line 1158 "paper/scene.nw"
/* the entry sec.key of the table, or NULL */
Scene_entry *scene_find(Scene_loader *L, const char *sec, const char *key);
/* sec[] = the sections of the named kind in the table, in the order of
   their first entries; their number (at most max) */
int scene_named_list(const Scene_loader *L, int kind, const char **sec, int max);
/* the slot of the named section sec among those of its kind, or -1 */
int scene_slot(const Scene_loader *L, const char *sec);
/* the table = the entries of the scene file L->path */
int scene_read_file(Scene_loader *L);
/* apply the override o = "section.key=value" onto the table */
int scene_apply_override(Scene_loader *L, const char *o);
/* the failure just told, as STATUS_MEMORY if errno e says memory */
int scene_for_memory(Scene_loader *L, int e);
/* whether buf, the start of a line, is or has begun a comment */
int scene_in_comment(const char *buf, int line);
#line 1640 "paper/scene.nw"
/* x = the number str: NULL, or why str is not a number */
const char *scene_to_real(const char *str, double *x);
/* L->last = the entry of sec.key, or its default; NULL if missing */
const Scene_entry *scene_entry(Scene_loader *L, const char *sec, const char *key);
/* k = the integer sec.key */
int scene_integer(Scene_loader *L, const char *sec, const char *key, int *k);
/* k = the index of the word sec.key among the words of its record */
int scene_word(Scene_loader *L, const char *sec, const char *key, int *k);
/* the field of s that sec.key's record names = the value of sec.key */
int scene_get(Scene_loader *L, Scene *s, const char *sec, const char *key);
/* refuse any key of sec that means nothing with selector = w */
int scene_refuse_unused(Scene_loader *L, const char *sec, const char *selector,
                        const char *w);
#line 2229 "paper/scene.nw"
/* [design] initial: alpha0 at the N+1 nodes */
int scene_read_initial(Scene_loader *L, Scene *s);
/* buf = file, relative to the directory of the scene file; 0 if it fits */
int scene_resolve(const char *scene, const char *file, char *buf, size_t size);
/* buf = path, absolute; 0 if it fits */
int scene_absolute(const char *path, char *buf, size_t size);
#line 1891 "paper/scene.nw"
/* the scene = the table, checked */
int scene_convert(Scene_loader *L, Scene *s);
#line 393 "paper/scene.nw"
#endif
