/* ROS 2 services the way rmw_cyclonedds carries them: a request writer on rq/<name>Request and a
 * reply reader on rr/<name>Reply, every payload starting with {uint64 guid; int64 seq}
 * (rmw_cyclonedds_cpp serdata.hpp); the client sets guid to its request writer's instance
 * handle and keeps only replies that echo it; USER_DATA clientid=/serviceid= lets the server
 * wait for the client's reply reader before answering (rmw_node.cpp check_for_response_reader),
 * without which the first reply can be lost to the discovery race. */
#include <stdio.h>
#include <string.h>

#include "dds_internal.h"

int ros_peek_header(const uint8_t *bytes, size_t n, sp_ros_rpc_header *h)
{
    cdr_in in;
    if (cdr_begin(&in, bytes, n, "request header", NULL)) return -1;
    return cdr_rpc_header(&in, h);
}

/* Both endpoints of one side of a service: the client writes requests and reads replies, the
 * server the other way round; both carry "<key>=<id>;" in USER_DATA. */
static int service_endpoints(ros_node *n, const char *fq, ros_type req, ros_type rep,
                             const char *key, const char *id, int client, dds_entity_t *on_req,
                             dds_entity_t *on_rep, sp_error *err)
{
    char topic[ROS_NAME_MAX + 16], ud[96];
    snprintf(ud, sizeof ud, "%s=%s;", key, id);
    if (ros_dds_name(fq, 'q', topic, sizeof topic, err)) return SP_E_ARG;
    *on_req = client ? ros_writer(n, req, topic, ROS_QOS_DEFAULT, ud, err)
                     : ros_reader(n, req, topic, ROS_QOS_DEFAULT, ud, err);
    if (*on_req < 0) return (int)*on_req;
    if (ros_dds_name(fq, 'r', topic, sizeof topic, err)) return SP_E_ARG;
    *on_rep = client ? ros_reader(n, rep, topic, ROS_QOS_DEFAULT, ud, err)
                     : ros_writer(n, rep, topic, ROS_QOS_DEFAULT, ud, err);
    return *on_rep < 0 ? (int)*on_rep : 0;
}

int ros_client_init(ros_client *c, ros_node *n, const char *service_fq, ros_type req,
                    ros_type rep, const char *clientid, sp_error *err)
{
    memset(c, 0, sizeof *c);
    snprintf(c->fq, sizeof c->fq, "%s", service_fq);
    int rc = service_endpoints(n, service_fq, req, rep, "clientid", clientid, 1, &c->req_w,
                               &c->rep_r, err);
    if (rc) return rc;
    dds_instance_handle_t ih;
    if (dds_get_instance_handle(c->req_w, &ih) != DDS_RETCODE_OK)
        return sp_error_set(err, SP_E_NET, "%s: no instance handle for the request writer",
                            service_fq);
    c->guid = ih;
    return 0;
}

void ros_client_fini(ros_client *c, ros_node *n)
{
    ros_endpoint_delete(n, c->req_w > 0 ? c->req_w : 0);
    ros_endpoint_delete(n, c->rep_r > 0 ? c->rep_r : 0);
    c->req_w = c->rep_r = 0;
}

int ros_client_ready(const ros_client *c)
{
    return c->req_w > 0 && ros_matched_readers(c->req_w) > 0 && ros_matched_writers(c->rep_r) > 0;
}

typedef struct {
    const ros_client *c;
    ros_sample_fn fn;
    void *ctx;
} client_filter;

static void filter_reply(void *ctx, const uint8_t *bytes, size_t n, const dds_sample_info_t *info)
{
    client_filter *f = ctx;
    sp_ros_rpc_header h;
    if (!ros_peek_header(bytes, n, &h) && h.guid == f->c->guid) f->fn(f->ctx, bytes, n, info);
}

int ros_client_take(ros_client *c, ros_sample_fn fn, void *ctx)
{
    client_filter f = {c, fn, ctx};
    return ros_take_raw(c->rep_r, filter_reply, &f, 64);
}

int ros_client_server_info(const ros_client *c, int *has_serviceid, sp_ros_distro *distro)
{
    dds_instance_handle_t hs[8];
    dds_return_t k = dds_get_matched_subscriptions(c->req_w, hs, 8);
    *has_serviceid = 0;
    *distro = SP_ROS_DISTRO_AUTO;
    if (k <= 0) return -1;
    for (int i = 0; i < k && i < 8; i++) {
        dds_builtintopic_endpoint_t *ep = dds_get_matched_subscription_data(c->req_w, hs[i]);
        if (!ep) continue;
        char v[128];
        if (!ros_qos_user_data_key(ep->qos, "serviceid", v, sizeof v)) *has_serviceid = 1;
        sp_ros_distro d = ros_qos_distro(ep->qos);
        if (d != SP_ROS_DISTRO_AUTO) *distro = d;
        dds_builtintopic_free_endpoint(ep);
    }
    return 0;
}

int ros_server_init(ros_server *s, ros_node *n, const char *service_fq, ros_type req,
                    ros_type rep, const char *serviceid, sp_error *err)
{
    memset(s, 0, sizeof *s);
    snprintf(s->fq, sizeof s->fq, "%s", service_fq);
    return service_endpoints(n, service_fq, req, rep, "serviceid", serviceid, 0, &s->req_r,
                             &s->rep_w, err);
}

void ros_server_fini(ros_server *s, ros_node *n)
{
    ros_endpoint_delete(n, s->req_r > 0 ? s->req_r : 0);
    ros_endpoint_delete(n, s->rep_w > 0 ? s->rep_w : 0);
    s->req_r = s->rep_w = 0;
}

int ros_server_take(ros_server *s, ros_sample_fn fn, void *ctx)
{
    return ros_take_raw(s->req_r, fn, ctx, 64);
}

typedef enum { CLIENT_GONE, CLIENT_MAYBE, CLIENT_YES } client_present;

static client_present reply_reader_present(ros_server *s, dds_instance_handle_t request_writer)
{
    dds_builtintopic_endpoint_t *wr = dds_get_matched_publication_data(s->req_r, request_writer);
    if (!wr) return CLIENT_GONE;
    char id[128], other[128];
    int has_id = !ros_qos_user_data_key(wr->qos, "clientid", id, sizeof id);
    dds_builtintopic_free_endpoint(wr);
    if (!has_id) return CLIENT_YES; /* rmw's backwards-compatibility rule */
    dds_instance_handle_t hs[64];
    dds_return_t k = dds_get_matched_subscriptions(s->rep_w, hs, 64);
    for (int i = 0; i < k && i < 64; i++) {
        dds_builtintopic_endpoint_t *rd = dds_get_matched_subscription_data(s->rep_w, hs[i]);
        if (!rd) continue;
        int same = !ros_qos_user_data_key(rd->qos, "clientid", other, sizeof other) &&
                   !strcmp(id, other);
        dds_builtintopic_free_endpoint(rd);
        if (same) return CLIENT_YES;
    }
    return CLIENT_MAYBE;
}

int ros_server_reply(ros_server *s, dds_instance_handle_t request_writer, const void *sample)
{
    double until = ros_now() + ROS_REPLY_WAIT_S;
    client_present st;
    while ((st = reply_reader_present(s, request_writer)) == CLIENT_MAYBE && ros_now() < until)
        dds_sleepfor(DDS_MSECS(5));
    if (st != CLIENT_YES) return SP_E_NET;
    return dds_write(s->rep_w, sample) < 0 ? SP_E_NET : 0;
}
