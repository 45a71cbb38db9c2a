/* Stand-in for av/video.c when FFmpeg's libraries are not found: the video writer fails with a
 * message naming the packages; pictures, plots and reports still work. */
#include <stddef.h>

#include "semsplat/media.h"

int sp_video_open(sp_video **v, const char *path, const sp_video_opts *o, sp_error *err)
{
    *v = NULL;
    return sp_error_set(err, SP_E_UNSUPPORTED,
                        "%s: writing video needs FFmpeg's libraries, which this build lacks: install "
                        "libavcodec-dev libavformat-dev libavutil-dev libswscale-dev "
                        "(scripts/install-deps.sh) and rebuild", path ? path : "video");
}

int sp_video_frame(sp_video *v, const uint8_t *rgb, int repeat, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "video: FFmpeg's libraries are not built in");
}

int sp_video_frame_canvas(sp_video *v, const sp_canvas *c, int repeat, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "video: FFmpeg's libraries are not built in");
}

long sp_video_frames(const sp_video *v) { return 0; }
int sp_video_fps(const sp_video *v) { return 0; }

int sp_video_close(sp_video *v, sp_error *err)
{
    return sp_error_set(err, SP_E_UNSUPPORTED, "video: FFmpeg's libraries are not built in");
}

void sp_video_discard(sp_video *v) { (void)v; }
