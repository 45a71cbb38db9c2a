/* The H.264 MP4 writer on FFmpeg's libraries: RGB frames -> libswscale (BT.709, limited range,
 * 4:2:0) -> libavcodec (libx264 when present, else any H.264 encoder) -> libavformat's MP4 muxer,
 * into <path>.tmp.<pid>, renamed on close. No process-wide FFmpeg setting is touched (its log
 * level stays the caller's); the encoder's information lines are demoted per context.
 * Compiled only when the four libraries are found (noav/video.c otherwise). */
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "media/media_internal.h"
#include "semsplat/media.h"

struct sp_video {
    char path[2048], tmp[2100];
    int width, height, fps;
    long frames;
    AVFormatContext *fmt;
    AVStream *stream;
    AVCodecContext *enc;
    AVFrame *frame;
    AVPacket *pkt;
    struct SwsContext *sws;
};

static int av_fail(sp_error *err, const sp_video *v, const char *what, int averr)
{
    char msg[AV_ERROR_MAX_STRING_SIZE] = "";
    av_strerror(averr, msg, sizeof msg);
    return sp_error_set(err, averr == AVERROR(ENOMEM) ? SP_E_NOMEM : SP_E_IO, "%s: %s: %s",
                        v->path, what, msg);
}

static void release(sp_video *v)
{
    sws_freeContext(v->sws);
    av_packet_free(&v->pkt);
    av_frame_free(&v->frame);
    avcodec_free_context(&v->enc);
    if (v->fmt) {
        if (v->fmt->pb) avio_closep(&v->fmt->pb);
        avformat_free_context(v->fmt);
    }
    free(v);
}

void sp_video_discard(sp_video *v)
{
    if (!v) return;
    int opened = v->fmt && v->fmt->pb;
    char tmp[sizeof v->tmp];
    memcpy(tmp, v->tmp, sizeof tmp);
    release(v);
    if (opened) unlink(tmp);
}

static int check_opts(const sp_video_opts *o, int *w, int *h, int *fps, sp_error *err)
{
    *w = o && o->width ? o->width : 1280;
    *h = o && o->height ? o->height : 720;
    *fps = o && o->fps ? o->fps : 25;
    if (*w < 16 || *h < 16 || *w > MEDIA_MAX_SIDE || *h > MEDIA_MAX_SIDE || (*w & 1) || (*h & 1))
        return sp_error_set(err, SP_E_ARG, "video %dx%d: expected even sides of 16..%d pixels "
                            "(H.264 4:2:0 halves the chroma)", *w, *h, MEDIA_MAX_SIDE);
    if (*fps < 1 || *fps > 120)
        return sp_error_set(err, SP_E_ARG, "video at %d frames/s: expected 1..120", *fps);
    if (o && (o->crf < 0 || o->crf > 51))
        return sp_error_set(err, SP_E_ARG, "video crf %d: expected 0..51", o->crf);
    if (o && (o->threads < 0 || o->threads > 64))
        return sp_error_set(err, SP_E_ARG, "video encoder threads %d: expected 0..64", o->threads);
    return 0;
}

static int open_encoder(sp_video *v, const sp_video_opts *o, sp_error *err)
{
    const AVCodec *codec = avcodec_find_encoder_by_name("libx264");
    int x264 = codec != NULL;
    if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!codec)
        return sp_error_set(err, SP_E_UNSUPPORTED,
                            "%s: this FFmpeg has no H.264 encoder (Debian's libavcodec59 brings "
                            "libx264; install it)", v->path);
    v->enc = avcodec_alloc_context3(codec);
    if (!v->enc) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", v->path);
    AVCodecContext *e = v->enc;
    e->width = v->width;
    e->height = v->height;
    e->time_base = (AVRational){1, v->fps};
    e->framerate = (AVRational){v->fps, 1};
    e->pix_fmt = AV_PIX_FMT_YUV420P;
    e->gop_size = 2 * v->fps;
    e->thread_count = o && o->threads ? o->threads : 2;
    e->colorspace = AVCOL_SPC_BT709;
    e->color_primaries = AVCOL_PRI_BT709;
    e->color_trc = AVCOL_TRC_BT709;
    e->color_range = AVCOL_RANGE_MPEG;
    /* One level quieter than FFmpeg's own: its information lines (x264's banner and statistics)
     * fall below the default log level while warnings and errors still show. */
    e->log_level_offset = 1;
    if (v->fmt->oformat->flags & AVFMT_GLOBALHEADER) e->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary *d = NULL;
    if (x264) {
        char crf[16];
        snprintf(crf, sizeof crf, "%d", o && o->crf ? o->crf : 23);
        av_dict_set(&d, "preset", o && o->preset ? o->preset : "veryfast", 0);
        av_dict_set(&d, "crf", crf, 0);
    }
    int rc = avcodec_open2(e, codec, &d);
    av_dict_free(&d);
    if (rc < 0) return av_fail(err, v, codec->name, rc);
    if ((rc = avcodec_parameters_from_context(v->stream->codecpar, e)) < 0)
        return av_fail(err, v, "stream parameters", rc);
    v->stream->time_base = e->time_base;
    return 0;
}

static int open_frames(sp_video *v, sp_error *err)
{
    v->frame = av_frame_alloc();
    v->pkt = av_packet_alloc();
    if (!v->frame || !v->pkt) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", v->path);
    v->frame->format = AV_PIX_FMT_YUV420P;
    v->frame->width = v->width;
    v->frame->height = v->height;
    int rc = av_frame_get_buffer(v->frame, 0);
    if (rc < 0) return av_fail(err, v, "frame buffer", rc);
    v->sws = sws_getContext(v->width, v->height, AV_PIX_FMT_RGB24, v->width, v->height,
                            AV_PIX_FMT_YUV420P, SWS_BILINEAR, NULL, NULL, NULL);
    if (!v->sws) return sp_error_set(err, SP_E_NOMEM, "%s: no RGB to YUV converter", v->path);
    /* BT.709 coefficients, full-range RGB in, limited-range YUV out (what the stream declares) */
    const int *bt709 = sws_getCoefficients(SWS_CS_ITU709);
    sws_setColorspaceDetails(v->sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    return 0;
}

int sp_video_open(sp_video **out, const char *path, const sp_video_opts *o, sp_error *err)
{
    *out = NULL;
    int w, h, fps, rc;
    if ((rc = check_opts(o, &w, &h, &fps, err))) return rc;
    if (!path || !*path) return sp_error_set(err, SP_E_ARG, "video: no output path");
    sp_video *v = calloc(1, sizeof *v);
    if (!v) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    if (snprintf(v->path, sizeof v->path, "%s", path) >= (int)sizeof v->path ||
        snprintf(v->tmp, sizeof v->tmp, "%s.tmp.%ld", path, (long)getpid()) >= (int)sizeof v->tmp) {
        free(v);
        return sp_error_set(err, SP_E_ARG, "video path too long: %.200s...", path);
    }
    v->width = w;
    v->height = h;
    v->fps = fps;
    if ((rc = avformat_alloc_output_context2(&v->fmt, NULL, "mp4", v->tmp)) < 0 || !v->fmt) {
        rc = av_fail(err, v, "MP4 muxer", rc < 0 ? rc : AVERROR(ENOMEM));
        release(v);
        return rc;
    }
    v->stream = avformat_new_stream(v->fmt, NULL);
    if (!v->stream) rc = sp_error_set(err, SP_E_NOMEM, "%s: out of memory", path);
    if (!rc) rc = open_encoder(v, o, err);
    if (!rc) rc = open_frames(v, err);
    if (!rc) {
        int a = avio_open(&v->fmt->pb, v->tmp, AVIO_FLAG_WRITE);
        if (a < 0) rc = av_fail(err, v, v->tmp, a);
    }
    if (!rc) {
        int a = avformat_write_header(v->fmt, NULL);
        if (a < 0) rc = av_fail(err, v, "MP4 header", a);
    }
    if (rc) {
        sp_video_discard(v);
        return rc;
    }
    *out = v;
    return 0;
}

/* Sends one frame (NULL = flush) and writes every packet the encoder hands back. */
static int encode(sp_video *v, AVFrame *f, sp_error *err)
{
    int rc = avcodec_send_frame(v->enc, f);
    if (rc < 0) return av_fail(err, v, "encoding", rc);
    for (;;) {
        rc = avcodec_receive_packet(v->enc, v->pkt);
        if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return 0;
        if (rc < 0) return av_fail(err, v, "encoding", rc);
        v->pkt->duration = 1; /* one frame: without it the MP4's last sample lasts 0 s */
        av_packet_rescale_ts(v->pkt, v->enc->time_base, v->stream->time_base);
        v->pkt->stream_index = v->stream->index;
        rc = av_interleaved_write_frame(v->fmt, v->pkt); /* takes the packet's reference */
        if (rc < 0) return av_fail(err, v, "writing", rc);
    }
}

int sp_video_frame(sp_video *v, const uint8_t *rgb, int repeat, sp_error *err)
{
    if (!v || !rgb) return sp_error_set(err, SP_E_ARG, "video frame: no %s", v ? "pixels" : "video");
    if (repeat < 1 || repeat > 100000)
        return sp_error_set(err, SP_E_ARG, "%s: frame repeated %d times: expected 1..100000",
                            v->path, repeat);
    int rc = av_frame_make_writable(v->frame);
    if (rc < 0) return av_fail(err, v, "frame buffer", rc);
    const uint8_t *src[1] = {rgb};
    const int stride[1] = {3 * v->width};
    sws_scale(v->sws, src, stride, 0, v->height, v->frame->data, v->frame->linesize);
    for (int r = 0; r < repeat; r++) {
        v->frame->pts = v->frames;
        if ((rc = encode(v, v->frame, err))) return rc;
        v->frames++;
    }
    return 0;
}

int sp_video_frame_canvas(sp_video *v, const sp_canvas *c, int repeat, sp_error *err)
{
    if (!v || !c) return sp_error_set(err, SP_E_ARG, "video frame: no %s", v ? "canvas" : "video");
    if (sp_canvas_width(c) != v->width || sp_canvas_height(c) != v->height)
        return sp_error_set(err, SP_E_ARG, "%s: canvas %dx%d for a %dx%d video", v->path,
                            sp_canvas_width(c), sp_canvas_height(c), v->width, v->height);
    uint8_t *rgb = malloc((size_t)v->width * v->height * 3);
    if (!rgb) return sp_error_set(err, SP_E_NOMEM, "%s: out of memory", v->path);
    sp_canvas_rgb(c, rgb);
    int rc = sp_video_frame(v, rgb, repeat, err);
    free(rgb);
    return rc;
}

long sp_video_frames(const sp_video *v) { return v ? v->frames : 0; }
int sp_video_fps(const sp_video *v) { return v ? v->fps : 0; }

int sp_video_close(sp_video *v, sp_error *err)
{
    if (!v) return sp_error_set(err, SP_E_ARG, "video close: no video");
    int rc = 0;
    if (v->frames == 0) rc = sp_error_set(err, SP_E_ARG, "%s: a video needs at least one frame", v->path);
    if (!rc) rc = encode(v, NULL, err);
    if (!rc) {
        int a = av_write_trailer(v->fmt);
        if (a < 0) rc = av_fail(err, v, "MP4 index", a);
    }
    if (!rc) {
        int a = avio_closep(&v->fmt->pb);
        if (a < 0) rc = av_fail(err, v, v->tmp, a);
    }
    if (!rc && rename(v->tmp, v->path) != 0)
        rc = sp_error_set(err, SP_E_IO, "%s: renaming %s: %s", v->path, v->tmp, strerror(errno));
    if (rc) {
        unlink(v->tmp);
        sp_video_discard(v);
        return rc;
    }
    release(v);
    return 0;
}
