/* SPDX-License-Identifier: GPL-3.0-or-later */
/* frccx.c — the hook of fricreg's CalculiX tier (fricreg's own code, not ccx's): the friction
 * law of each surface interaction, read from the job's laws file, and the call of fricreg's
 * element kernel at a contact point. ccx-fricreg.patch calls frccx_setup after each step's
 * input (ccx_2.20.c) and frccxl_ from ccx's four penalty-friction routines; build.sh compiles
 * this file into the private patched ccx only (README.md here: never installed or shipped).
 *
 * The laws file, JOB.fricreg beside JOB.inp (ccx reads no such file: a deck with one still
 * runs in stock ccx, as Coulomb everywhere). One interaction a line, '#' to the end of a line
 * a comment, words separated by blanks:
 *   NAME  jenkins_3d                 Coulomb, ccx's own law (one slider: its slip vector)
 *   NAME  iwan_3d  NS [c_1 .. c_NS]  NS sliders in parallel, slider s of stiffness xk / NS and
 *                                    bound c_s mu |F_n| (c_s > 0, sum 1 to 1e-12; by default
 *                                    c_s = 2 s / (NS (NS + 1)): slider s slips from a stretch of
 *                                    2 s / (NS + 1) times mu |F_n| / xk)
 * NAME is a *SURFACE INTERACTION's name (any case; ccx keeps names in capitals; a name the deck
 * does not define is an error), or * for every interaction no line names. mu and the stick slope (xk = slope times the slave area) are
 * *FRICTION's, as ccx's. An interaction the file does not name runs ccx's own code, unchanged.
 *
 * The state: jenkins_3d's slider is ccx's slip vector, xstate(1:3). iwan_3d keeps its 3 NS
 * slider coordinates past ccx's own 9 numbers, in xstate(10:9+3 NS): the deck's *DEPVAR must be
 * at least 9 + 3 NS (the call says so otherwise); ccx's slip vector gets t - F / xk, the
 * Iwan's equivalent slip (ccx's contact output reads it). */
#define _POSIX_C_SOURCE 200809L /* strtok_r */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <fricreg_element.h>

#define NAME_LEN 80 /* ccx's matname entries: 80 characters, blank-padded */
#define LINE_LEN 4096

/* One interaction's law: no type (ccx's own code), or the type, its sliders and c_s. */
struct law {
    const fricreg_element_type *type;
    size_t ns;
    double c[FRICREG_ELEMENT_MAX_SLIDERS];
};

static struct law *laws; /* [nlaws], by ccx's material index - 1 */
static int nlaws;

/* Whether ccx's blank-padded name (80 characters) equals word, case aside. */
static int same_name(const char *padded, const char *word)
{
    size_t n = strlen(word);
    if (n > NAME_LEN)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (toupper((unsigned char)padded[i]) != toupper((unsigned char)word[i]))
            return 0;
    for (size_t i = n; i < NAME_LEN; i++)
        if (padded[i] != ' ' && padded[i] != '\0')
            return 0;
    return 1;
}

/* Parses a law's words (after the name) into *law; 0, or -1 with the reason printed. */
static int parse_law(char *words, const char *where, struct law *law)
{
    char *save = NULL, *name = strtok_r(words, " \t\r\n", &save);
    law->type = name != NULL ? fricreg_element_lookup(name) : NULL;
    law->ns = 1;
    law->c[0] = 1.0;
    if (law->type != NULL && law->type == fricreg_element_lookup("jenkins_3d")) {
        if (strtok_r(NULL, " \t\r\n", &save) == NULL)
            return 0;
        printf(" *ERROR in fricreg's laws file %s: jenkins_3d takes no numbers\n", where);
        return -1;
    }
    if (law->type == NULL || law->type != fricreg_element_lookup("iwan_3d")) {
        printf(" *ERROR in fricreg's laws file %s: '%s' is not jenkins_3d or iwan_3d\n", where,
               name != NULL ? name : "");
        return -1;
    }
    char *word = strtok_r(NULL, " \t\r\n", &save), *end = NULL;
    long ns = word != NULL ? strtol(word, &end, 10) : 0;
    if (word == NULL || *end != '\0' || ns < 1 || ns > FRICREG_ELEMENT_MAX_SLIDERS) {
        printf(" *ERROR in fricreg's laws file %s: iwan_3d needs its sliders, 1 to %d\n", where,
               FRICREG_ELEMENT_MAX_SLIDERS);
        return -1;
    }
    law->ns = (size_t)ns;
    law->type = fricreg_element_sliders(law->type, law->ns);
    double sum = 0.0;
    size_t given = 0;
    while ((word = strtok_r(NULL, " \t\r\n", &save)) != NULL && given < law->ns) {
        law->c[given] = strtod(word, &end);
        if (*end != '\0' || !(law->c[given] > 0.0) || !isfinite(law->c[given])) {
            printf(" *ERROR in fricreg's laws file %s: c_%zu = '%s' must be a number > 0\n", where,
                   given + 1, word);
            return -1;
        }
        sum += law->c[given++];
    }
    if (given == 0)
        for (size_t s = 0; s < law->ns; s++)
            law->c[s] = 2.0 * (double)(s + 1) / ((double)law->ns * (double)(law->ns + 1));
    else if (given != law->ns || word != NULL || fabs(sum - 1.0) > 1e-12) {
        printf(" *ERROR in fricreg's laws file %s: iwan_3d %zu needs %zu numbers c_s summing "
               "to 1 (has %zu%s, sum %.17g)\n",
               where, law->ns, law->ns, given, word != NULL ? " and more" : "", sum);
        return -1;
    }
    return 0;
}

/* Applies one line of the file (number lineno) to the laws of the nmat materials. */
static int apply_line(char *line, const char *path, int lineno, const char *matname, int nmat,
                      int *named)
{
    char *hash = strchr(line, '#'), where[1000], name[NAME_LEN + 1] = "";
    if (hash != NULL)
        *hash = '\0';
    int used = 0;
    if (sscanf(line, "%80s%n", name, &used) != 1)
        return 0; /* a blank or comment line */
    snprintf(where, sizeof where, "%s, line %d", path, lineno);
    struct law law;
    if (parse_law(line + used, where, &law) != 0)
        return -1;
    int star = strcmp(name, "*") == 0, found = 0;
    for (int i = 0; i < nmat; i++) {
        if (star ? named[i] : !same_name(matname + (size_t)NAME_LEN * (size_t)i, name))
            continue;
        if (!star) /* a line that names an interaction wins over *, wherever it stands */
            named[i] = 1;
        laws[i] = law;
        found = 1;
    }
    if (!star && !found) { /* a misspelt name would leave its interaction to ccx unseen */
        printf(" *ERROR in fricreg's laws file %s: no *SURFACE INTERACTION is named %s\n", where,
               name);
        return -1;
    }
    return 0;
}

/* Reads JOB.fricreg (jobnamec: ccx's job name) for the nmat materials whose names are
 * matname[80 nmat]: every interaction's law. A missing file leaves every interaction to ccx.
 * Returns 0, or -1 (the reason printed) for a file it cannot read or a line it refuses. */
int frccx_setup(const char *jobnamec, const char *matname, int nmat)
{
    char path[900];
    snprintf(path, sizeof path, "%s.fricreg", jobnamec);
    free(laws);
    laws = calloc((size_t)(nmat > 0 ? nmat : 1), sizeof *laws);
    int *named = calloc((size_t)(nmat > 0 ? nmat : 1), sizeof *named);
    nlaws = nmat;
    FILE *file = fopen(path, "r");
    if (laws == NULL || named == NULL || file == NULL) {
        free(named);
        if (file != NULL)
            fclose(file);
        return laws != NULL ? 0 : -1;
    }
    /* named interactions first, then *: two passes over the lines */
    char line[LINE_LEN];
    int status = 0;
    for (int pass = 0; pass < 2 && status == 0; pass++) {
        rewind(file);
        for (int lineno = 1; status == 0 && fgets(line, sizeof line, file) != NULL; lineno++) {
            char first[NAME_LEN + 1] = "";
            sscanf(line, "%80s", first);
            if ((strcmp(first, "*") == 0) == (pass == 1))
                status = apply_line(line, path, lineno, matname, nmat, named);
        }
    }
    fclose(file);
    free(named);
    return status;
}

/* The law of ccx's material imat (1-based) at one contact point, from Fortran (arguments by
 * reference): xk the stick slope times the slave area, b = mu |F_n| the slip bound (1e300 for
 * ccx's elastic predictor), nstate ccx's numbers per point, sold[nstate] the point's state at
 * the start of the increment, t[3] the relative tangential displacement. Writes f[3] the
 * tangential force, dfdt[3 x 3] dF_i/dt_j (column-major: Fortran's dfdt(i, j)), dfdb[3] dF/db,
 * snew[nstate] the state after the call (its slots past ccx's 9 and the slip vector; ccx's
 * own 4 to 9 untouched), se = sum_s k_s |t - w_s'|^2 and ve = sum_s phi_s |w_s' - w_s| (ccx's
 * elastic and dissipated energy forms), and *used: 1 done, 0 no law for imat (ccx's own code
 * runs; nothing written), -1 refused (the reason printed; ccx stops). */
void frccxl_(const int *imat, const double *xk, const double *b, const int *nstate,
             const double *sold, const double *t, double *f, double *dfdt, double *dfdb,
             double *snew, double *se, double *ve, int *used)
{
    const struct law *law = *imat >= 1 && *imat <= nlaws ? &laws[*imat - 1] : NULL;
    *used = 0;
    if (law == NULL || law->type == NULL)
        return;
    size_t ns = law->ns, np = 2 * ns;
    int iwan = law->type != fricreg_element_lookup("jenkins_3d");
    size_t first = iwan ? 9 : 0; /* the sliders' first slot */
    if ((size_t)*nstate < first + 3 * ns) {
        printf(" *ERROR in fricreg's hook: iwan_3d %zu keeps %zu numbers past ccx's 9: *DEPVAR "
               "%zu in the deck (has %d)\n",
               ns, 3 * ns, 9 + 3 * ns, *nstate);
        *used = -1;
        return;
    }
    double p[np], dfdp[3 * np], w[3 * ns], wn[3 * ns], tangent[9];
    for (size_t s = 0; s < ns; s++) {
        p[s] = *xk / (double)ns;
        p[ns + s] = law->c[s] * *b;
    }
    memcpy(w, sold + first, 3 * ns * sizeof *w);
    int status = fricreg_element_eval(law->type, p, w, t, f, tangent, dfdp, wn);
    if (status != FRICREG_OK) {
        char msg[300];
        fricreg_element_explain(law->type, p, w, t, msg, sizeof msg);
        printf(" *ERROR in fricreg's hook: %s\n", msg);
        *used = -1;
        return;
    }
    *se = *ve = 0.0;
    for (int a = 0; a < 3; a++) {
        dfdb[a] = 0.0;
        for (int c = 0; c < 3; c++)
            dfdt[a + 3 * c] = tangent[3 * a + c];
    }
    for (size_t s = 0; s < ns; s++) {
        double stretch2 = 0.0, moved2 = 0.0;
        for (int a = 0; a < 3; a++) {
            dfdb[a] += law->c[s] * dfdp[np * (size_t)a + ns + s];
            stretch2 += (t[a] - wn[3 * s + a]) * (t[a] - wn[3 * s + a]);
            moved2 += (wn[3 * s + a] - w[3 * s + a]) * (wn[3 * s + a] - w[3 * s + a]);
        }
        *se += p[s] * stretch2;
        *ve += p[ns + s] * sqrt(moved2);
    }
    memcpy(snew + first, wn, 3 * ns * sizeof *wn);
    if (iwan)
        for (int a = 0; a < 3; a++)
            snew[a] = t[a] - f[a] / *xk;
    *used = 1;
}
