/* semsplat agent: talk to the robot in words. One command from the arguments, or an interactive
 * session on stdin; each answer is printed and written to --out as JSON with its tool trace. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_ros.h"
#include "semsplat/agent.h"

static void help(void)
{
    printf("usage: semsplat agent --model DIR [flags] [\"go to the refrigerator\" ...]\n"
           "       (no command: an interactive session; 'quit' ends it, Ctrl-C stops the robot)\n\n"
           "  --out DIR             answers as answer_NNN.json with the tool trace, and images\n"
           "                        (default agent-out)\n"
           "  --llm builtin|openai|anthropic   who reads the commands (default builtin: offline)\n"
           "  --llm-preset P        openai (default), llama.cpp, ollama, vllm\n"
           "  --llm-url URL         base URL (else $OPENAI_BASE_URL / $ANTHROPIC_BASE_URL / preset)\n"
           "  --llm-model NAME      model name (required for hosted endpoints)\n"
           "  --llm-timeout S       per request (default 60); --llm-retries N (default 2)\n"
           "  --max-steps N         model turns per command (default 8)\n"
           "  --confirm             ask before every motion\n"
           "  --max-speed M/S       robot speed limit (default 0.4, at most %.1f)\n"
           "  --start X,Y,YAW       the offline robot's start pose\n"
           "  --ros                 drive a ROS 2 robot (Nav2 NavigateToPose over DDS) instead of\n"
           "                        the offline one; --ros-wait S for its first pose (default 10)\n"
           "  --device cpu|cuda|auto, --threads N   where the map is queried and rendered\n"
           "  --json                print each answer as JSON; --quiet, --verbose\n"
           "API keys come only from OPENAI_API_KEY / ANTHROPIC_API_KEY.\n\nROS flags (with --ros):\n%s",
           SP_AGENT_SPEED_LIMIT, cli_ros_help);
}

static sp_agent_session *g_session; /* for the Ctrl-C handler */

static void on_sigint(int sig)
{
    (void)sig;
    if (g_session) sp_agent_session_cancel(g_session);
    signal(SIGINT, SIG_DFL); /* a second Ctrl-C ends the program */
}

static int confirm(void *user, const char *what)
{
    FILE *tty = fopen("/dev/tty", "r+");
    FILE *in = tty ? tty : stdin, *out = tty ? tty : stderr;
    fprintf(out, "semsplat agent: %s? [y/N] ", what);
    fflush(out);
    char line[64] = "";
    int yes = fgets(line, sizeof line, in) && (line[0] == 'y' || line[0] == 'Y');
    if (tty) fclose(tty);
    return yes;
}

static int answer(sp_agent_session *s, const char *text, int json)
{
    sp_agent_answer a;
    sp_error err = {0};
    signal(SIGINT, on_sigint);
    int rc = sp_agent_session_ask(s, text, &a, &err);
    signal(SIGINT, SIG_DFL);
    if (json) {
        char *j = sp_agent_answer_json(&a);
        if (j) printf("%s\n", j);
        free(j);
    } else {
        printf("%s\n", a.text ? a.text : "");
        for (int i = 0; i < a.n_images; i++) printf("  image: %s\n", a.images[i]);
        if (a.json_path[0]) printf("  trace: %s\n", a.json_path);
    }
    fflush(stdout);
    sp_agent_answer_free(&a);
    return rc ? cli_fail("agent", &err) : 0;
}

static int interactive(sp_agent_session *s, int json)
{
    char line[1200];
    int tty = isatty(0), failed = 0;
    for (;;) {
        if (tty) fprintf(stderr, "> "), fflush(stderr);
        if (!fgets(line, sizeof line, stdin)) break;
        line[strcspn(line, "\r\n")] = 0;
        if (!strcmp(line, "quit") || !strcmp(line, "exit")) break;
        if (line[0]) failed |= answer(s, line, json);
    }
    return failed;
}

static int parse_brain(const char *v, int *brain)
{
    if (!strcmp(v, "builtin")) *brain = SP_AGENT_BRAIN_BUILTIN;
    else if (!strcmp(v, "openai")) *brain = SP_AGENT_BRAIN_OPENAI;
    else if (!strcmp(v, "anthropic")) *brain = SP_AGENT_BRAIN_ANTHROPIC;
    else return cli_usage_error("agent", "--llm: '%s' is not builtin, openai or anthropic", v);
    return 0;
}

static int parse_start(const char *v, sp_agent_config *cfg)
{
    char extra;
    if (sscanf(v, "%lf,%lf,%lf%c", &cfg->start.x, &cfg->start.y, &cfg->start.yaw, &extra) != 3 ||
        !isfinite(cfg->start.x) || !isfinite(cfg->start.y) || !isfinite(cfg->start.yaw))
        return cli_usage_error("agent", "--start: '%s' is not X,Y,YAW", v);
    cfg->have_start = 1;
    return 0;
}

int cmd_agent(int argc, char **argv)
{
    sp_agent_config cfg = sp_agent_config_default();
    const char *texts[64], *v;
    int n_texts = 0, json = 0, bad = 0, r;
    cli_common c = cli_common_default();
    cfg.out_dir = "agent-out";
    cfg.confirm_fn = confirm;
    cli_ros_defaults(&cfg.ros);
    cfg.ros.node_name = "semsplat_agent";
    for (int i = 1; i < argc; i++) {
        long n;
        double d;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return help(), 0;
        if ((r = cli_common_flag("agent", argc, argv, &i, CLI_ALL, &c))) {
            if (r == 2) return 2;
        } else if (cli_ros_flag("agent", argc, argv, &i, &cfg.ros, &bad)) {
            if (bad) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--model", &bad))) cfg.model_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--out", &bad))) cfg.out_dir = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--llm-preset", &bad))) cfg.llm.preset = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--llm-url", &bad))) cfg.llm.base_url = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--llm-model", &bad))) cfg.llm.model = v;
        else if ((v = cli_flag_value(argc, argv, &i, "--llm", &bad))) {
            if (parse_brain(v, &cfg.brain)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--llm-timeout", &bad))) {
            if (cli_parse_float("agent", "--llm-timeout", v, &d)) return 2;
            cfg.llm.timeout_s = d;
        } else if ((v = cli_flag_value(argc, argv, &i, "--llm-retries", &bad))) {
            if (cli_parse_int("agent", "--llm-retries", v, &n)) return 2;
            cfg.llm.max_retries = (int)n;
        } else if ((v = cli_flag_value(argc, argv, &i, "--max-steps", &bad))) {
            if (cli_parse_int("agent", "--max-steps", v, &n)) return 2;
            cfg.llm.max_steps = (int)n;
        } else if ((v = cli_flag_value(argc, argv, &i, "--max-speed", &bad))) {
            if (cli_parse_float("agent", "--max-speed", v, &d)) return 2;
            cfg.max_speed_mps = d;
        } else if ((v = cli_flag_value(argc, argv, &i, "--ros-wait", &bad))) {
            if (cli_parse_float("agent", "--ros-wait", v, &cfg.ros_wait_s)) return 2;
        } else if ((v = cli_flag_value(argc, argv, &i, "--start", &bad))) {
            if (parse_start(v, &cfg)) return 2;
        } else if (!strcmp(argv[i], "--confirm")) cfg.confirm = 1;
        else if (!strcmp(argv[i], "--ros")) cfg.use_ros = 1;
        else if (!strcmp(argv[i], "--json")) json = 1;
        else if (argv[i][0] == '-' && argv[i][1] == '-' && !bad)
            return cli_usage_error("agent", "unknown flag '%s'", argv[i]);
        else if (!bad) {
            if (n_texts == 64) return cli_usage_error("agent", "at most 64 commands at once");
            texts[n_texts++] = argv[i];
        }
        if (bad) return 2;
    }
    if (!cfg.model_dir) return cli_usage_error("agent", "--model DIR is required");
    /* every flag checked before any work (the world, the robot, a server) */
    if (!(cfg.llm.timeout_s > 0 && cfg.llm.timeout_s <= 3600))
        return cli_usage_error("agent", "--llm-timeout %g: expected 0..3600 seconds", cfg.llm.timeout_s);
    if (cfg.llm.max_retries < 0 || cfg.llm.max_retries > 20)
        return cli_usage_error("agent", "--llm-retries %d: expected 0..20", cfg.llm.max_retries);
    if (cfg.llm.max_steps < 1 || cfg.llm.max_steps > 100)
        return cli_usage_error("agent", "--max-steps %d: expected 1..100", cfg.llm.max_steps);
    if (!(cfg.max_speed_mps > 0 && cfg.max_speed_mps <= SP_AGENT_SPEED_LIMIT))
        return cli_usage_error("agent", "--max-speed %g: expected above 0, at most %.1f", cfg.max_speed_mps,
                               SP_AGENT_SPEED_LIMIT);
    static const char *const presets[] = {"openai", "llama.cpp", "ollama", "vllm"};
    int known = !cfg.llm.preset;
    for (size_t k = 0; k < sizeof presets / sizeof presets[0] && !known; k++) known = !strcmp(cfg.llm.preset, presets[k]);
    if (!known) return cli_usage_error("agent", "--llm-preset '%s': expected openai, llama.cpp, ollama or vllm", cfg.llm.preset);
    sp_error merr = {0};
    if (cfg.out_dir && sp_mkdirs(cfg.out_dir, &merr)) return cli_fail("agent", &merr);
    sp_log log = cli_log(&c, SP_LOG_INFO);
    cfg.log = &log;
    sp_error err = {0};
    sp_agent_session *s = NULL;
    if (cli_device_open("agent", &c, &cfg.device)) return 1;
    if (sp_agent_session_open(&s, &cfg, &err)) {
        sp_device_free(cfg.device);
        return cli_fail("agent", &err);
    }
    g_session = s;
    int failed = 0;
    for (int i = 0; i < n_texts; i++) failed |= answer(s, texts[i], json);
    if (n_texts == 0) failed = interactive(s, json);
    g_session = NULL;
    sp_agent_session_close(s);
    sp_device_free(cfg.device);
    return failed ? 1 : 0;
}
