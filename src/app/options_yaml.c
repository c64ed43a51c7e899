/* An options file (a YAML scene) that does not parse: the file and the line, before PETSc reads it (PETSc 3.18's
   loader says only "YAML parser loading error"). Runs before SlepcInitialize, on the command line's
   -options_file F (F.yaml, F.yml) and -options_file_yaml F, with libyaml, the parser PETSc uses. */
#include <roller.h>
#include <stdio.h>
#include <string.h>
#include <yaml.h>

static int IsYaml(const char *opt, const char *file)
{
  size_t n = strlen(file);

  if (!strcmp(opt, "-options_file_yaml")) return 1;
  return !strcmp(opt, "-options_file") && ((n > 5 && !strcmp(file + n - 5, ".yaml")) || (n > 4 && !strcmp(file + n - 4, ".yml")));
}

/* 0 if the file parses (or cannot be opened: PETSc says so itself), else 1 after one line on stderr. */
static int Parse(const char *file)
{
  FILE         *fp = fopen(file, "rb");
  yaml_parser_t parser;
  yaml_event_t  event;
  int           done = 0, bad = 0;

  if (!fp) return 0;
  if (!yaml_parser_initialize(&parser)) {
    fclose(fp);
    return 0;
  }
  yaml_parser_set_input_file(&parser, fp);
  while (!done) {
    if (!yaml_parser_parse(&parser, &event)) {
      if (parser.context)
        fprintf(stderr, "roller: options file %s, line %lu: YAML error: %s (%s from line %lu)\n", file, (unsigned long)parser.problem_mark.line + 1, parser.problem ? parser.problem : "cannot parse", parser.context, (unsigned long)parser.context_mark.line + 1);
      else fprintf(stderr, "roller: options file %s, line %lu: YAML error: %s\n", file, (unsigned long)parser.problem_mark.line + 1, parser.problem ? parser.problem : "cannot parse");
      bad = 1;
      break;
    }
    done = event.type == YAML_STREAM_END_EVENT;
    yaml_event_delete(&event);
  }
  yaml_parser_delete(&parser);
  fclose(fp);
  return bad;
}

int RollerOptionsFilesParse(int argc, char **argv)
{
  int bad = 0;

  for (int i = 1; i + 1 < argc; ++i)
    if (IsYaml(argv[i], argv[i + 1])) bad |= Parse(argv[i + 1]);
  return bad;
}
