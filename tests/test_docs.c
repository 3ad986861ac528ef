/* The language reference must document every channel the parser accepts:
 * a new row in tl_channels.c without a row in docs/timeline.md fails. */
#include <stdlib.h>

#include "timeline/tl_channels.h"
#include "tl_test.h"

int main(int argc, char **argv)
{
    if (argc < 2)
        return 1;
    FILE *f = fopen(argv[1], "rb");
    CHECK(f != NULL);
    if (!f)
        TEST_END();
    static char text[1 << 20];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    for (int i = 0; i < tl_channel_count(); i++) {
        char row[128];
        snprintf(row, sizeof row, "| `%s`", tl_channel_at(i)->name);
        CHECK_STR_CONTAINS(text, row);
    }
    TEST_END();
}
