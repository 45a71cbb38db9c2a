// A ROS 2 peer on eProsima Fast DDS (ROS 2's default middleware) for tests/ros/test_fastdds.c,
// compiled in the test build only. It uses the names rmw_fastrtps uses (topics rt/..., types
// <pkg>::msg::dds_::<Name>_) and serializes with Fast CDR, an implementation independent of
// Cyclone's and of ours:
//   - publishes nav_msgs/Odometry on rt/<ns>/odom at 20 Hz with known values;
//   - subscribes (reliable, transient local) to rt/<ns>/semsplat/map (OccupancyGrid) and
//     rt/<ns>/semsplat/path_1, _2 (Path), and prints what it decoded:
//       map <width> <height> <resolution> <origin_x> <origin_y> <origin_yaw> <checksum> <frame>
//       path <k> <n> <x0> <y0> <yaw0> <xn> <yn> <yawn> <frame>
// Exits 0 once it has the map and both paths and has published 40 odometry messages, 1 after
// --seconds without them. Discovery is unicast on 127.0.0.1 only (no multicast), to the
// standard RTPS ports of participant ids 0..31 in the domain.
#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

using namespace eprosima::fastdds::dds;
using eprosima::fastcdr::Cdr;
using eprosima::fastcdr::FastBuffer;
using eprosima::fastrtps::rtps::SerializedPayload_t;
using eprosima::fastrtps::rtps::InstanceHandle_t;

struct Stamp { int32_t sec = 0; uint32_t nanosec = 0; };
struct Pose { double p[7] = {0, 0, 0, 0, 0, 0, 1}; };  // x y z qx qy qz qw
struct PoseStamped { Stamp stamp; std::string frame; Pose pose; };
struct Odom { Stamp stamp; std::string frame, child; Pose pose; double pcov[36] = {}; double twist[6] = {}; double tcov[36] = {}; };
struct Grid { Stamp stamp; std::string frame; Stamp load; float res = 0; uint32_t w = 0, h = 0; Pose origin; std::vector<int8_t> data; };
struct Path { Stamp stamp; std::string frame; std::vector<PoseStamped> poses; };

static void put(Cdr &c, const Stamp &s) { c << s.sec << s.nanosec; }
static void get(Cdr &c, Stamp &s) { c >> s.sec >> s.nanosec; }
static void put(Cdr &c, const Pose &p) { for (double v : p.p) c << v; }
static void get(Cdr &c, Pose &p) { for (double &v : p.p) c >> v; }
static void get(Cdr &c, PoseStamped &p) { get(c, p.stamp); c >> p.frame; get(c, p.pose); }

// One TopicDataType per message: the name as rmw_fastrtps builds it, Fast CDR (DDS_CDR: the
// encapsulation header, then classic CDR aligned from after it) for the bytes.
template <typename T>
class RosType : public TopicDataType {
public:
    RosType(const char *name, void (*ser)(Cdr &, const T &), void (*de)(Cdr &, T &))
        : ser_(ser), de_(de) {
        setName(name);
        m_typeSize = 1 << 22;
        m_isGetKeyDefined = false;
    }
    bool serialize(void *data, SerializedPayload_t *payload) override {
        FastBuffer fb(reinterpret_cast<char *>(payload->data), payload->max_size);
        Cdr c(fb, Cdr::DEFAULT_ENDIAN, Cdr::DDS_CDR);
        payload->encapsulation = c.endianness() == Cdr::BIG_ENDIANNESS ? CDR_BE : CDR_LE;
        try {
            c.serialize_encapsulation();
            ser_(c, *static_cast<T *>(data));
        } catch (...) { return false; }
        payload->length = static_cast<uint32_t>(c.getSerializedDataLength());
        return true;
    }
    bool deserialize(SerializedPayload_t *payload, void *data) override {
        FastBuffer fb(reinterpret_cast<char *>(payload->data), payload->length);
        Cdr c(fb, Cdr::DEFAULT_ENDIAN, Cdr::DDS_CDR);
        try {
            c.read_encapsulation();
            de_(c, *static_cast<T *>(data));
        } catch (...) { return false; }
        return true;
    }
    std::function<uint32_t()> getSerializedSizeProvider(void *) override {
        return [] { return 1u << 22; };
    }
    void *createData() override { return new T(); }
    void deleteData(void *d) override { delete static_cast<T *>(d); }
    bool getKey(void *, InstanceHandle_t *, bool) override { return false; }
private:
    void (*ser_)(Cdr &, const T &);
    void (*de_)(Cdr &, T &);
};

static void ser_odom(Cdr &c, const Odom &o) {
    put(c, o.stamp); c << o.frame << o.child; put(c, o.pose);
    c.serializeArray(o.pcov, 36); c.serializeArray(o.twist, 6); c.serializeArray(o.tcov, 36);
}
static void de_odom(Cdr &c, Odom &o) {
    get(c, o.stamp); c >> o.frame >> o.child; get(c, o.pose);
    c.deserializeArray(o.pcov, 36); c.deserializeArray(o.twist, 6); c.deserializeArray(o.tcov, 36);
}
static void ser_grid(Cdr &, const Grid &) {}
static void de_grid(Cdr &c, Grid &g) {
    get(c, g.stamp); c >> g.frame; get(c, g.load); c >> g.res >> g.w >> g.h; get(c, g.origin);
    uint32_t n; c >> n;
    if (n > (1u << 24)) throw std::runtime_error("grid too large");
    g.data.resize(n);
    if (n) c.deserializeArray(g.data.data(), n);
}
static void ser_path(Cdr &, const Path &) {}
static void de_path(Cdr &c, Path &p) {
    get(c, p.stamp); c >> p.frame;
    uint32_t n; c >> n;
    if (n > 100000) throw std::runtime_error("path too long");
    p.poses.resize(n);
    for (auto &ps : p.poses) get(c, ps);
}

static double yaw_of(const Pose &p) {
    return std::atan2(2 * (p.p[6] * p.p[5] + p.p[3] * p.p[4]), 1 - 2 * (p.p[4] * p.p[4] + p.p[5] * p.p[5]));
}

int main(int argc, char **argv) {
    int domain = 0;
    std::string ns;
    double seconds = 20;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!strcmp(argv[i], "--domain")) domain = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "--ns")) ns = argv[i + 1];
        else if (!strcmp(argv[i], "--seconds")) seconds = atof(argv[i + 1]);
    }
    DomainParticipantQos pq;
    pq.name("semsplat_fastdds_peer");
    auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
    udp->interfaceWhiteList.push_back("127.0.0.1");
    pq.transport().user_transports.push_back(udp);
    pq.transport().use_builtin_transports = false;
    pq.wire_protocol().builtin.avoid_builtin_multicast = true;
    for (int id = 0; id < 32; id++) {  // SPDP unicast ports: 7400 + 250 d + 10 + 2 id
        eprosima::fastrtps::rtps::Locator_t peer;
        eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, 127, 0, 0, 1);
        peer.port = static_cast<uint32_t>(7400 + 250 * domain + 10 + 2 * id);
        pq.wire_protocol().builtin.initialPeersList.push_back(peer);
    }
    DomainParticipant *pp = DomainParticipantFactory::get_instance()->create_participant(domain, pq);
    if (!pp) { fprintf(stderr, "fastdds_peer: no participant\n"); return 2; }
    TypeSupport odom_t(new RosType<Odom>("nav_msgs::msg::dds_::Odometry_", ser_odom, de_odom));
    TypeSupport grid_t(new RosType<Grid>("nav_msgs::msg::dds_::OccupancyGrid_", ser_grid, de_grid));
    TypeSupport path_t(new RosType<Path>("nav_msgs::msg::dds_::Path_", ser_path, de_path));
    odom_t.register_type(pp);
    grid_t.register_type(pp);
    path_t.register_type(pp);
    Topic *odom_topic = pp->create_topic("rt" + ns + "/odom", odom_t.get_type_name(), TOPIC_QOS_DEFAULT);
    Topic *map_topic = pp->create_topic("rt" + ns + "/semsplat/map", grid_t.get_type_name(), TOPIC_QOS_DEFAULT);
    Topic *p1 = pp->create_topic("rt" + ns + "/semsplat/path_1", path_t.get_type_name(), TOPIC_QOS_DEFAULT);
    Topic *p2 = pp->create_topic("rt" + ns + "/semsplat/path_2", path_t.get_type_name(), TOPIC_QOS_DEFAULT);
    Publisher *pub = pp->create_publisher(PUBLISHER_QOS_DEFAULT);
    Subscriber *sub = pp->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    DataWriterQos wq = DATAWRITER_QOS_DEFAULT;
    wq.reliability().kind = RELIABLE_RELIABILITY_QOS;
    DataWriter *odom_w = pub->create_datawriter(odom_topic, wq);
    DataReaderQos rq = DATAREADER_QOS_DEFAULT;
    rq.reliability().kind = RELIABLE_RELIABILITY_QOS;
    rq.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
    rq.history().kind = KEEP_LAST_HISTORY_QOS;
    rq.history().depth = 1;
    DataReader *map_r = sub->create_datareader(map_topic, rq);
    DataReader *path_r[2] = {sub->create_datareader(p1, rq), sub->create_datareader(p2, rq)};
    if (!odom_w || !map_r || !path_r[0] || !path_r[1]) { fprintf(stderr, "fastdds_peer: endpoints\n"); return 2; }

    Odom o;
    o.frame = "odom";
    o.child = "base_link";
    int published = 0;
    bool have_map = false, have_path[2] = {false, false};
    auto t0 = std::chrono::steady_clock::now();
    int rc = 1;
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < seconds) {
        // Known values the test checks: x = 1.25 + 0.01 k, y = -0.5, yaw 0.3, vx 0.2, wz -0.1.
        o.stamp.sec = 1700000000 + published;
        o.stamp.nanosec = 500000000;
        o.pose.p[0] = 1.25 + 0.01 * published;
        o.pose.p[1] = -0.5;
        o.pose.p[5] = std::sin(0.15);
        o.pose.p[6] = std::cos(0.15);
        o.twist[0] = 0.2;
        o.twist[5] = -0.1;
        o.pcov[0] = 0.01;
        if (odom_w->write(&o)) published++;
        SampleInfo info;
        Grid g;
        while (map_r->take_next_sample(&g, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            uint32_t sum = 0;
            for (size_t i = 0; i < g.data.size(); i++) sum += static_cast<uint32_t>(i + 1) * static_cast<uint8_t>(g.data[i]);
            printf("map %u %u %.9g %.9g %.9g %.9g %u %s %zu\n", g.w, g.h, g.res, g.origin.p[0], g.origin.p[1],
                   yaw_of(g.origin), sum, g.frame.c_str(), g.data.size());
            have_map = true;
        }
        for (int k = 0; k < 2; k++) {
            Path p;
            while (path_r[k]->take_next_sample(&p, &info) == ReturnCode_t::RETCODE_OK) {
                if (!info.valid_data || p.poses.empty()) continue;
                const Pose &a = p.poses.front().pose, &b = p.poses.back().pose;
                printf("path %d %zu %.9g %.9g %.9g %.9g %.9g %.9g %s\n", k + 1, p.poses.size(), a.p[0], a.p[1],
                       yaw_of(a), b.p[0], b.p[1], yaw_of(b), p.frame.c_str());
                have_path[k] = true;
            }
        }
        fflush(stdout);
        if (have_map && have_path[0] && have_path[1] && published >= 40) { rc = 0; break; }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    printf("published %d odometry; map %d, paths %d %d\n", published, have_map, have_path[0], have_path[1]);
    pp->delete_contained_entities();
    DomainParticipantFactory::get_instance()->delete_participant(pp);
    return rc;
}
