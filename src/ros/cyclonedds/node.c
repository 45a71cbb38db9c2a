/* A Cyclone DDS participant that other ROS 2 nodes see as one of theirs (rmw_cyclonedds
 * conventions): participant USER_DATA enclave=/;, readers and writers with rmw's QoS mapping,
 * ros_discovery_info so `ros2 node list` shows us, and distro detection from the peers'
 * endpoint USER_DATA (Jazzy's rmw puts typehash=RIHS01_...; on every endpoint, Humble's none). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <dds/ddsi/ddsi_serdata.h>

#include "dds_internal.h"

/* Every type we put on a topic, and the module prefix to strip from the distro variants so the
 * DDS type name is ROS's (see humble.idl). */
static const struct {
    const dds_topic_descriptor_t *desc;
    const char *strip;
} types[RT_COUNT] = {
    [RT_ODOMETRY] = {&nav_msgs_msg_dds__Odometry__desc, NULL},
    [RT_PATH] = {&nav_msgs_msg_dds__Path__desc, NULL},
    [RT_OCCUPANCY_GRID] = {&nav_msgs_msg_dds__OccupancyGrid__desc, NULL},
    [RT_TF] = {&tf2_msgs_msg_dds__TFMessage__desc, NULL},
    [RT_STATUS_ARRAY] = {&action_msgs_msg_dds__GoalStatusArray__desc, NULL},
    [RT_CANCEL_REQ] = {&action_msgs_srv_dds__CancelGoal_Request__desc, NULL},
    [RT_CANCEL_REP] = {&action_msgs_srv_dds__CancelGoal_Response__desc, NULL},
    [RT_NAV_GOAL_REQ] = {&nav2_msgs_action_dds__NavigateToPose_SendGoal_Request__desc, NULL},
    [RT_NAV_GOAL_REP] = {&nav2_msgs_action_dds__NavigateToPose_SendGoal_Response__desc, NULL},
    [RT_NAV_RESULT_REQ] = {&nav2_msgs_action_dds__NavigateToPose_GetResult_Request__desc, NULL},
    [RT_NAV_FEEDBACK] = {&nav2_msgs_action_dds__NavigateToPose_FeedbackMessage__desc, NULL},
    [RT_PATH_GOAL_REQ] = {&nav2_msgs_action_dds__ComputePathToPose_SendGoal_Request__desc, NULL},
    [RT_PATH_GOAL_REP] = {&nav2_msgs_action_dds__ComputePathToPose_SendGoal_Response__desc, NULL},
    [RT_PATH_RESULT_REQ] = {&nav2_msgs_action_dds__ComputePathToPose_GetResult_Request__desc,
                            NULL},
    [RT_PATH_FEEDBACK] = {&nav2_msgs_action_dds__ComputePathToPose_FeedbackMessage__desc, NULL},
    [RT_NAV_RESULT_REP_HUMBLE] =
        {&humble_nav2_msgs_action_dds__NavigateToPose_GetResult_Response__desc, "humble::"},
    [RT_NAV_RESULT_REP_JAZZY] =
        {&jazzy_nav2_msgs_action_dds__NavigateToPose_GetResult_Response__desc, "jazzy::"},
    [RT_PATH_RESULT_REP_HUMBLE] =
        {&humble_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response__desc, "humble::"},
    [RT_PATH_RESULT_REP_JAZZY] =
        {&jazzy_nav2_msgs_action_dds__ComputePathToPose_GetResult_Response__desc, "jazzy::"},
    [RT_DISCOVERY_HUMBLE] = {&humble_rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc,
                             "humble::"},
    [RT_DISCOVERY_JAZZY] = {&jazzy_rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc,
                            "jazzy::"},
};

ros_type ros_type_for(ros_type humble_variant, sp_ros_distro d)
{
    return d == SP_ROS_DISTRO_JAZZY ? (ros_type)(humble_variant + 1) : humble_variant;
}

const dds_topic_descriptor_t *ros_type_descriptor(ros_type t) { return types[t].desc; }

/* The descriptor to create topics with: distro variants get a copy named as ROS names them. */
static const dds_topic_descriptor_t *node_descriptor(ros_node *n, ros_type t)
{
    const dds_topic_descriptor_t *d = types[t].desc;
    if (!types[t].strip) return d;
    if (!n->renamed[t]) {
        dds_topic_descriptor_t copy = {
            .m_size = d->m_size, .m_align = d->m_align, .m_flagset = d->m_flagset,
            .m_nkeys = d->m_nkeys, .m_typename = d->m_typename + strlen(types[t].strip),
            .m_keys = d->m_keys, .m_nops = d->m_nops, .m_ops = d->m_ops, .m_meta = d->m_meta,
            .type_information = d->type_information, .type_mapping = d->type_mapping,
            .restrict_data_representation = d->restrict_data_representation};
        n->renamed[t] = malloc(sizeof copy);
        if (!n->renamed[t]) return NULL;
        memcpy(n->renamed[t], &copy, sizeof copy);
    }
    return n->renamed[t];
}

/* Cyclone for one machine: the loopback interface, no multicast, discovery by unicast to the
 * participant ports of 127.0.0.1 (ParticipantIndex auto gives each participant its own). */
static const char *loopback_config =
    "<CycloneDDS><Domain id=\"any\"><General>"
    "<Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
    "<AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>30</MaxAutoParticipantIndex>"
    "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
    "</Domain></CycloneDDS>";

static int make_domain(const sp_ros_options *o, sp_error *err)
{
    const char *xml = o->dds_config ? o->dds_config : o->loopback_only ? loopback_config : NULL;
    if (!xml) return 0; /* Cyclone reads $CYCLONEDDS_URI when the participant is created */
    dds_entity_t d = dds_create_domain((dds_domainid_t)o->domain_id, xml);
    /* PRECONDITION_NOT_MET: this process already created the domain (another node in it). */
    if (d < 0 && d != DDS_RETCODE_PRECONDITION_NOT_MET)
        return sp_error_set(err, SP_E_NET, "DDS domain %d: the Cyclone configuration was "
                            "refused (%s)", o->domain_id, dds_strretcode(d));
    return 0;
}

static int make_builtin_readers(ros_node *n, sp_error *err)
{
    n->builtin_pub = dds_create_reader(n->pp, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, NULL, NULL);
    n->builtin_sub = dds_create_reader(n->pp, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, NULL, NULL);
    if (n->builtin_pub < 0 || n->builtin_sub < 0)
        return sp_error_set(err, SP_E_NET, "DDS discovery readers: %s",
                            dds_strretcode(n->builtin_pub < 0 ? n->builtin_pub : n->builtin_sub));
    return 0;
}

int ros_node_create(ros_node **out, const sp_ros_options *o, sp_error *err)
{
    if (o->domain_id < 0 || o->domain_id > 232)
        return sp_error_set(err, SP_E_ARG, "ROS domain id %d: 0..232 (DDS port mapping)",
                            o->domain_id);
    if (ros_check_namespace(o->ns, err)) return SP_E_ARG;
    const char *name = o->node_name && o->node_name[0] ? o->node_name : "semsplat";
    char fq[ROS_NAME_MAX];
    if (ros_fq_name("", name, fq, sizeof fq, err) || strchr(name, '/'))
        return sp_error_set(err, SP_E_ARG, "node name '%s': one ROS token", name);
    if (make_domain(o, err)) return SP_E_NET;
    ros_node *n = calloc(1, sizeof *n);
    if (!n) return sp_error_set(err, SP_E_NOMEM, "ros node");
    n->domain_id = o->domain_id;
    n->distro = o->distro;
    n->configured = o->distro != SP_ROS_DISTRO_AUTO;
    snprintf(n->ns, sizeof n->ns, "%s", o->ns && strcmp(o->ns, "/") ? o->ns : "");
    snprintf(n->name, sizeof n->name, "%s", name);
    dds_qos_t *qos = dds_create_qos();
    const char *enclave = "enclave=/;";
    dds_qset_userdata(qos, enclave, strlen(enclave));
    n->pp = dds_create_participant((dds_domainid_t)o->domain_id, qos, NULL);
    dds_delete_qos(qos);
    if (n->pp < 0) {
        int rc = sp_error_set(err, SP_E_NET, "DDS participant in domain %d: %s (check "
                              "CYCLONEDDS_URI and the network interface)", o->domain_id,
                              dds_strretcode(n->pp));
        free(n);
        return rc;
    }
    dds_get_guid(n->pp, &n->guid);
    if (make_builtin_readers(n, err) || (n->configured && ros_node_announce(n, err))) {
        ros_node_free(n);
        return err ? err->code : SP_E_NET;
    }
    *out = n;
    return 0;
}

void ros_node_free(ros_node *n)
{
    if (!n) return;
    if (n->pp > 0) dds_delete(n->pp);
    for (int i = 0; i < RT_COUNT; i++) free(n->renamed[i]);
    free(n);
}

/* ---- USER_DATA ---- */

int ros_qos_user_data_key(const dds_qos_t *qos, const char *key, char *out, size_t cap)
{
    void *ud = NULL;
    size_t sz = 0;
    if (!qos || !dds_qget_userdata(qos, &ud, &sz) || !ud) return -1;
    const char *s = ud, *end = s + sz;
    size_t klen = strlen(key);
    int found = -1;
    while (s < end && found < 0) {
        const char *semi = memchr(s, ';', (size_t)(end - s));
        const char *stop = semi ? semi : end;
        const char *eq = memchr(s, '=', (size_t)(stop - s));
        if (eq && (size_t)(eq - s) == klen && !memcmp(s, key, klen)) {
            size_t vlen = (size_t)(stop - eq - 1);
            if (vlen >= cap) vlen = cap - 1;
            memcpy(out, eq + 1, vlen);
            out[vlen] = 0;
            found = 0;
        }
        s = stop + 1;
    }
    dds_free(ud);
    return found;
}

sp_ros_distro ros_qos_distro(const dds_qos_t *qos)
{
    char v[96];
    if (!ros_qos_user_data_key(qos, "semsplat_distro", v, sizeof v)) {
        if (!strcmp(v, "jazzy")) return SP_ROS_DISTRO_JAZZY;
        if (!strcmp(v, "humble")) return SP_ROS_DISTRO_HUMBLE;
    }
    if (!ros_qos_user_data_key(qos, "typehash", v, sizeof v)) return SP_ROS_DISTRO_JAZZY;
    return SP_ROS_DISTRO_AUTO;
}

/* Looks at endpoints discovered so far: any ROS endpoint (rt/ rq/ rr/) of another participant
 * with typehash= says Jazzy; a ROS endpoint without says Humble unless a Jazzy one shows up. */
static void scan_builtin(ros_node *n, dds_entity_t rd)
{
    void *samples[32] = {NULL};
    dds_sample_info_t infos[32];
    int k = dds_take(rd, samples, infos, 32, 32);
    for (int i = 0; i < k; i++) {
        const dds_builtintopic_endpoint_t *ep = samples[i];
        if (!infos[i].valid_data || !ep->topic_name) continue;
        if (!memcmp(&ep->participant_key, &n->guid, sizeof n->guid)) continue;
        const char *t = ep->topic_name;
        if (strncmp(t, "rt/", 3) && strncmp(t, "rq/", 3) && strncmp(t, "rr/", 3)) continue;
        sp_ros_distro d = ros_qos_distro(ep->qos);
        if (d == SP_ROS_DISTRO_JAZZY) n->seen_jazzy = 1;
        else n->seen_humble = 1;
    }
    if (k > 0) dds_return_loan(rd, samples, k);
}

sp_ros_distro ros_node_distro(ros_node *n)
{
    if (n->distro != SP_ROS_DISTRO_AUTO) return n->distro;
    scan_builtin(n, n->builtin_pub);
    scan_builtin(n, n->builtin_sub);
    return n->seen_jazzy ? SP_ROS_DISTRO_JAZZY
           : n->seen_humble ? SP_ROS_DISTRO_HUMBLE : SP_ROS_DISTRO_AUTO;
}

int ros_node_set_distro(ros_node *n, sp_ros_distro d, sp_error *err)
{
    if (n->distro == d && n->disc_writer > 0) return 0;
    if (n->disc_writer > 0) { /* the other distro's layout */
        ros_endpoint_delete(n, n->disc_writer);
        n->disc_writer = 0;
    }
    n->distro = d;
    return ros_node_announce(n, err);
}

void ros_node_csid(ros_node *n, char *out, size_t cap)
{
    /* rmw uses the participant's GUID prefix and a counter; only string equality matters. */
    int k = 0;
    for (int i = 0; i < 12 && k + 3 < (int)cap; i++) k += snprintf(out + k, cap - k, "%02x", n->guid.v[i]);
    snprintf(out + k, cap - k, ".%u", ++n->csid_counter);
}

/* ---- endpoints ---- */

static dds_qos_t *make_qos(ros_node *n, ros_qos q, const char *extra)
{
    dds_qos_t *qos = dds_create_qos();
    dds_qset_reliability(qos, q.reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT,
                         DDS_MSECS(100));
    dds_qset_durability(qos, q.transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL
                                               : DDS_DURABILITY_VOLATILE);
    dds_history_kind_t hk = q.depth > 0 ? DDS_HISTORY_KEEP_LAST : DDS_HISTORY_KEEP_ALL;
    dds_qset_history(qos, hk, q.depth > 0 ? q.depth : 1);
    if (q.transient_local) /* as rmw_cyclonedds create_readwrite_qos does */
        dds_qset_durability_service(qos, 0, hk, q.depth > 0 ? q.depth : 1, DDS_LENGTH_UNLIMITED,
                                    DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    dds_qset_writer_data_lifecycle(qos, false);
    dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
    dds_qset_data_representation(qos, 1, &xcdr1);
    /* Never empty: Jazzy peers warn about endpoints whose USER_DATA they cannot parse. */
    char ud[256];
    snprintf(ud, sizeof ud, "%ssemsplat_distro=%s;", extra ? extra : "",
             sp_ros_distro_name(n->distro));
    dds_qset_userdata(qos, ud, strlen(ud));
    return qos;
}

static dds_entity_t make_endpoint(ros_node *n, ros_type t, const char *topic, ros_qos q,
                                  const char *extra, int is_reader, sp_error *err)
{
    const dds_topic_descriptor_t *desc = node_descriptor(n, t);
    if (!desc) return sp_error_set(err, SP_E_NOMEM, "descriptor");
    if (is_reader ? n->n_readers >= ROS_MAX_ENDPOINTS : n->n_writers >= ROS_MAX_ENDPOINTS)
        return sp_error_set(err, SP_E_ARG, "more than %d DDS endpoints", ROS_MAX_ENDPOINTS);
    dds_entity_t tp = dds_create_topic(n->pp, desc, topic, NULL, NULL);
    if (tp < 0)
        return sp_error_set(err, SP_E_NET, "DDS topic %s (%s): %s", topic, desc->m_typename,
                            dds_strretcode(tp));
    dds_qos_t *qos = make_qos(n, q, extra);
    dds_entity_t e = is_reader ? dds_create_reader(n->pp, tp, qos, NULL)
                               : dds_create_writer(n->pp, tp, qos, NULL);
    dds_delete_qos(qos);
    if (e < 0)
        return sp_error_set(err, SP_E_NET, "DDS %s on %s: %s", is_reader ? "reader" : "writer",
                            topic, dds_strretcode(e));
    dds_guid_t g;
    dds_get_guid(e, &g);
    if (is_reader) n->readers[n->n_readers++] = g;
    else n->writers[n->n_writers++] = g;
    return e;
}

dds_entity_t ros_reader(ros_node *n, ros_type t, const char *topic, ros_qos q, const char *extra,
                        sp_error *err)
{
    return make_endpoint(n, t, topic, q, extra, 1, err);
}

dds_entity_t ros_writer(ros_node *n, ros_type t, const char *topic, ros_qos q, const char *extra,
                        sp_error *err)
{
    return make_endpoint(n, t, topic, q, extra, 0, err);
}

static void forget(dds_guid_t *list, int *count, const dds_guid_t *g)
{
    for (int i = 0; i < *count; i++)
        if (!memcmp(&list[i], g, sizeof *g)) {
            list[i] = list[--*count];
            return;
        }
}

void ros_endpoint_delete(ros_node *n, dds_entity_t e)
{
    if (e <= 0) return;
    dds_guid_t g;
    if (dds_get_guid(e, &g) == DDS_RETCODE_OK) {
        forget(n->readers, &n->n_readers, &g);
        forget(n->writers, &n->n_writers, &g);
    }
    dds_delete(e);
}

/* ---- samples ---- */

int ros_take_raw(dds_entity_t reader, ros_sample_fn fn, void *ctx, int max)
{
    int taken = 0;
    while (taken < max) {
        struct ddsi_serdata *sd = NULL;
        dds_sample_info_t info;
        if (dds_takecdr(reader, &sd, 1, &info, DDS_ANY_STATE) != 1) break;
        taken++;
        if (info.valid_data) {
            ddsrt_iovec_t iov;
            uint32_t size = ddsi_serdata_size(sd);
            struct ddsi_serdata *ref = ddsi_serdata_to_ser_ref(sd, 0, size, &iov);
            fn(ctx, iov.iov_base, iov.iov_len, &info);
            ddsi_serdata_to_ser_unref(ref, &iov);
        }
        ddsi_serdata_unref(sd);
    }
    return taken;
}

int ros_matched_writers(dds_entity_t reader)
{
    dds_subscription_matched_status_t st;
    return dds_get_subscription_matched_status(reader, &st) == DDS_RETCODE_OK
               ? (int)st.current_count : 0;
}

int ros_matched_readers(dds_entity_t writer)
{
    dds_publication_matched_status_t st;
    return dds_get_publication_matched_status(writer, &st) == DDS_RETCODE_OK
               ? (int)st.current_count : 0;
}

void ros_nap(void) { dds_sleepfor(DDS_MSECS(10)); }

/* ---- ros_discovery_info ---- */

/* One node with our endpoints' GIDs: the 16-byte DDSI GUID, zero-padded to 24 on Humble
 * (rmw_cyclonedds convert_guid_to_gid). Written for both layouts by one macro. */
#define ANNOUNCE(distro_prefix)                                                                 \
    static int announce_##distro_prefix(ros_node *n)                                           \
    {                                                                                          \
        distro_prefix##_rmw_dds_common_msg_dds__ParticipantEntitiesInfo_ s;                    \
        distro_prefix##_rmw_dds_common_msg_dds__NodeEntitiesInfo_ node;                        \
        distro_prefix##_rmw_dds_common_msg_dds__Gid_ rd[ROS_MAX_ENDPOINTS], wr[ROS_MAX_ENDPOINTS]; \
        memset(&s, 0, sizeof s);                                                               \
        memset(&node, 0, sizeof node);                                                         \
        memset(rd, 0, sizeof rd);                                                              \
        memset(wr, 0, sizeof wr);                                                              \
        memcpy(s.gid.data, n->guid.v, 16);                                                     \
        snprintf(node.node_namespace, sizeof node.node_namespace, "%s", n->ns[0] ? n->ns : "/"); \
        snprintf(node.node_name, sizeof node.node_name, "%s", n->name);                        \
        for (int i = 0; i < n->n_readers; i++) memcpy(rd[i].data, n->readers[i].v, 16);        \
        for (int i = 0; i < n->n_writers; i++) memcpy(wr[i].data, n->writers[i].v, 16);        \
        node.reader_gid_seq._length = node.reader_gid_seq._maximum = (uint32_t)n->n_readers;  \
        node.reader_gid_seq._buffer = rd;                                                      \
        node.writer_gid_seq._length = node.writer_gid_seq._maximum = (uint32_t)n->n_writers;  \
        node.writer_gid_seq._buffer = wr;                                                      \
        s.node_entities_info_seq._length = s.node_entities_info_seq._maximum = 1;              \
        s.node_entities_info_seq._buffer = &node;                                              \
        return dds_write(n->disc_writer, &s);                                                  \
    }
ANNOUNCE(humble)
ANNOUNCE(jazzy)
#undef ANNOUNCE

int ros_node_announce(ros_node *n, sp_error *err)
{
    if (n->distro == SP_ROS_DISTRO_AUTO) return 0; /* the layout is not known yet */
    if (n->disc_writer <= 0) {
        ros_type t = ros_type_for(RT_DISCOVERY_HUMBLE, n->distro);
        n->disc_writer = ros_writer(n, t, "ros_discovery_info", ROS_QOS_LATCHED, NULL, err);
        if (n->disc_writer < 0) {
            n->disc_writer = 0;
            return err ? err->code : SP_E_NET;
        }
    }
    int rc = n->distro == SP_ROS_DISTRO_JAZZY ? announce_jazzy(n) : announce_humble(n);
    if (rc < 0)
        return sp_error_set(err, SP_E_NET, "ros_discovery_info: %s", dds_strretcode(rc));
    return 0;
}
