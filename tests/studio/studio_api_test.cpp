// The studio's API over real HTTP: a server in this process on a free loopback port, the real
// compiler and lavapipe behind it, a folder of gallery graphs to work in.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <httplib.h>

#include "javascript_json.h"
#include "scratch_dir.h"
#include "studio/studio_server.h"
#include "tool/command_outcome.h"

namespace fg::studio {

namespace {
namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

class StudioApiTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        scratch = new fg::test::ScratchDir("fg_studio_api");
        work = scratch->path();
        fs::create_directories(work / "folder");
        for (const char* name : {"mandelbulb.json", "menger.json"})
            fs::copy_file(fs::path(FG_SOURCE_DIR) / "graphs/gallery" / name, work / "folder" / name);
        fs::copy_file(fs::path(FG_SOURCE_DIR) / "graphs/formulas/mandelbox.json", work / "folder" / "formula_box.json");
        std::ofstream(work / "outside.json") << "{\"outside\": true}";
        ctx = new vk::Context(fgplay::render_context_options(true, ""));
        SessionOptions options;
        options.folder = (work / "folder").string();
        options.eye_size = 64;
        session = new StudioSession(*ctx, options);
        ServerOptions server_options;
        server_options.port = 0;
        server_options.max_body_bytes = 1u << 20;
        server = new StudioServer(*session, server_options);
        std::string error;
        ASSERT_TRUE(server->bind(error)) << error;
        listener = new std::thread([] { server->listen(); });
    }
    static void TearDownTestSuite() {
        server->stop();
        listener->join();
        delete listener;
        delete server;
        delete session;
        EXPECT_EQ(ctx->validation_errors(), 0u);
        delete ctx;
        delete scratch;
    }

    static httplib::Client client() {
        httplib::Client c("127.0.0.1", server->port());
        c.set_read_timeout(120, 0);
        return c;
    }
    static json post(const std::string& path, const json& body, int expect = 200) {
        auto r = client().Post(path.c_str(), body.dump(), "application/json");
        EXPECT_TRUE(r);
        if (!r) return {};
        EXPECT_EQ(r->status, expect) << path << ": " << r->body;
        return r->get_header_value("Content-Type") == "application/json" ? json::parse(r->body) : json{{"bytes", r->body}};
    }
    static json graph(const std::string& name) { return json::parse(read(work / "folder" / name)); }
    // Queues the graph and waits for its compile.
    static json compiled(const json& g) {
        auto revision = post("/api/edit", {{"graph", g}}, 202)["revision"].get<std::uint64_t>();
        auto r = client().Get(fmt::format("/api/state?after={}&wait_ms=10000", revision).c_str());
        auto state = json::parse(r->body);
        EXPECT_GE(state["revision"].get<std::uint64_t>(), revision);
        return state;
    }
    static std::string frame(const json& params, std::string* revision = nullptr) {
        auto r = client().Post("/api/frame", json{{"params", params}}.dump(), "application/json");
        EXPECT_TRUE(r && r->status == 200) << (r ? r->body : "no reply");
        EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
        if (revision && r) *revision = r->get_header_value("X-Fg-Revision");
        return r ? r->body : "";
    }

    static inline fg::test::ScratchDir* scratch = nullptr;
    static inline fs::path work;
    static inline vk::Context* ctx = nullptr;
    static inline StudioSession* session = nullptr;
    static inline StudioServer* server = nullptr;
    static inline std::thread* listener = nullptr;
};

TEST_F(StudioApiTest, ServesThePageAndTheNodeLibrary) {
    auto page = client().Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("Fractograph Studio"), std::string::npos);
    auto nodes = json::parse(client().Get("/api/nodes")->body)["nodes"];
    bool bulb = false;
    for (const auto& n : nodes) bulb |= n["type"] == "fractal.mandelbulb" && n["category"] == "fractal";
    EXPECT_TRUE(bulb);
}

// The palette leaves formula stages out (they live in a body), and a formula node added from it
// starts from its example's whole body: a node that compiles, not an error.
TEST_F(StudioApiTest, MarksFormulaStagesAndGivesTheFormulaNodeABody) {
    auto nodes = json::parse(client().Get("/api/nodes")->body)["nodes"];
    json example;
    std::size_t stages = 0;
    std::set<std::string> in_body;
    for (const auto& n : nodes) {
        stages += n["stage"].get<bool>();
        if (n["in_body"].get<bool>()) in_body.insert(n["type"].get<std::string>());
        if (n["type"] == "fractal.formula") example = n["example"];
    }
    EXPECT_GE(stages, 10u);
    // A body's palette: stages and maths with a tangent rule, not jumps or shapes.
    EXPECT_TRUE(in_body.count("stage.box_fold") && in_body.count("stage.orbit") && in_body.count("math.multiply"));
    EXPECT_FALSE(in_body.count("math.floor") || in_body.count("prim.sphere"));
    ASSERT_TRUE(example.contains("formula")) << example;
    json g = json::parse(R"({"format": "fractograph-graph", "version": 1, "nodes": [], "outputs": {"distance": "f.distance"}})");
    json node = {{"id", "f"}, {"type", "fractal.formula"}};
    for (auto it = example.begin(); it != example.end(); ++it) node[it.key()] = it.value();
    g["nodes"].push_back(node);
    fg::Diagnostics diag;
    EXPECT_TRUE(fg::load_and_lower(g.dump(), fg::NodeLibrary::builtin(), diag)) << diag.format();
}

TEST_F(StudioApiTest, RefusesAForeignHostOrOrigin) {
    auto c = client();
    auto r = c.Get("/api/nodes", {{"Host", "evil.example:80"}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 403);
    EXPECT_NE(r->body.find("Host"), std::string::npos);
    auto before = session->edits().submitted();
    r = c.Post("/api/edit", {{"Origin", "http://evil.example"}}, json{{"graph", graph("mandelbulb.json")}}.dump(),
               "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 403);
    EXPECT_NE(r->body.find("Origin"), std::string::npos);
    EXPECT_EQ(session->edits().submitted(), before);
    r = c.Get("/api/nodes", {{"Origin", fmt::format("http://127.0.0.1:{}", server->port())}});
    EXPECT_EQ(r->status, 200);
}

TEST_F(StudioApiTest, RefusesPathsOutsideItsFolder) {
    for (const std::string& path : std::vector<std::string>{"../outside.json", "%2E%2E/outside.json", (work / "outside.json").string(), "/etc/passwd"}) {
        auto r = client().Get(("/api/graph?path=" + path).c_str());
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 400) << path << ": " << r->body;
        EXPECT_EQ(r->body.find("outside\": true"), std::string::npos);
    }
    auto g = graph("mandelbulb.json");
    for (const std::string& path : std::vector<std::string>{"../written.json", "sub/../../written.json", (work / "written.json").string()}) {
        auto reply = post("/api/save", {{"path", path}, {"graph", g}}, 400);
        EXPECT_TRUE(reply["error"].get<std::string>().find("refused") != std::string::npos ||
                    reply["error"].get<std::string>().find("outside") != std::string::npos) << reply;
        post("/api/export", {{"path", path + ".fgpack"}, {"graph", g}}, 400);
    }
    EXPECT_FALSE(fs::exists(work / "written.json"));
    EXPECT_EQ(read(work / "outside.json"), "{\"outside\": true}");
}

TEST_F(StudioApiTest, RefusesOversizedBodiesAndBrokenJsonAndKeepsServing) {
    auto r = client().Post("/api/edit", std::string(2u << 20, ' '), "application/json");
    if (r) EXPECT_EQ(r->status, 413);   // or the connection is closed before the body is read
    auto broken = post("/api/edit", json(), 400);
    r = client().Post("/api/edit", "{\"graph\": {\"nodes\": [", "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400);
    EXPECT_NE(r->body.find("not JSON"), std::string::npos) << r->body;
    r = client().Post("/api/edit", "[1, 2]", "application/json");
    EXPECT_EQ(r->status, 400);
    EXPECT_NE(r->body.find("JSON object"), std::string::npos);
    r = client().Post("/api/edit", "{\"graph\": 3}", "application/json");
    EXPECT_EQ(r->status, 400);
    EXPECT_NE(r->body.find("'graph' is required"), std::string::npos);
    EXPECT_EQ(client().Get("/api/nodes")->status, 200);
}

TEST_F(StudioApiTest, AParameterChangesTheFrameWithoutARecompile) {
    auto state = compiled(graph("mandelbulb.json"));
    ASSERT_TRUE(state["ok"]) << state;
    auto compiles = session->compiles();
    std::string at8 = frame({{"power", 8.0}});
    std::string at5 = frame({{"power", 5.0}});
    EXPECT_EQ(at8.substr(0, 8), "\x89PNG\r\n\x1a\n");
    EXPECT_NE(at8, at5);
    EXPECT_EQ(frame({{"power", 8.0}}), at8);
    EXPECT_EQ(session->compiles(), compiles);
}

TEST_F(StudioApiTest, AnEditRecompilesOnlyThePassItChangedAndAnExportIsTheWholeOptimisedPack) {
    auto g = graph("mandelbulb.json");
    ASSERT_TRUE(compiled(g)["ok"]);
    for (auto& node : g["nodes"])
        if (node["id"] == "tone") node["inputs"]["s"] = 0.6123;   // a value no other test compiles
    const auto pipelines = session->preview().pipelines_built();
    auto state = compiled(g);
    ASSERT_TRUE(state["ok"]) << state;
    // Of the passes the preview plays, only shade evaluates the colour: one pass compiled, and one
    // pipeline built (both eyes' shade passes share it; the marching passes' and the probe's are kept).
    EXPECT_EQ(state["passes_compiled"], 1) << state;
    EXPECT_EQ(session->preview().pipelines_built() - pipelines, 1u);
    EXPECT_EQ(frame({}).substr(0, 8), "\x89PNG\r\n\x1a\n");

    post("/api/export", {{"path", "edited.fgpack"}, {"graph", g}});
    Diagnostics diag;
    auto full = compile_graph(g.dump(), NodeLibrary::builtin(), {}, diag);
    ASSERT_TRUE(full) << diag.format();
    const auto bytes = pack_bytes(*full);
    EXPECT_EQ(read(work / "folder" / "edited.fgpack"), std::string(bytes.begin(), bytes.end()));
}

TEST_F(StudioApiTest, AFormulaBodysNumberIsAUniformSoEditingItCompilesNoPass) {
    auto g = graph("formula_box.json");
    ASSERT_TRUE(compiled(g)["ok"]);
    const std::string before = frame({});
    bool edited = false;
    for (auto& node : g["nodes"])
        if (node.contains("formula"))
            for (auto& stage : node["formula"]["groups"][0]["nodes"])
                if (stage["type"] == "stage.sphere_fold") {
                    stage["inputs"]["min_radius"] = 0.3123;   // a shape no other test compiles
                    edited = true;
                }
    ASSERT_TRUE(edited);
    const auto pipelines = session->preview().pipelines_built();
    auto state = compiled(g);
    ASSERT_TRUE(state["ok"]) << state;
    // The new radius is a parameter's default: the passes' code is the same, so none is compiled
    // and no pipeline built, and the frame shows the new shape.
    EXPECT_EQ(state["passes_compiled"], 0) << state;
    EXPECT_EQ(session->preview().pipelines_built(), pipelines);
    EXPECT_NE(frame({}), before);
    // A stage added to the body changes the code: that compiles.
    for (auto& node : g["nodes"])
        if (node.contains("formula")) {
            auto& nodes = node["formula"]["groups"][0]["nodes"];
            nodes.push_back({{"id", "turn"}, {"type", "stage.rotate"}, {"inputs", {{"z", nodes.back()["id"]}, {"axis", {0, 1, 0}}, {"angle_deg", 10}}}});
        }
    state = compiled(g);
    ASSERT_TRUE(state["ok"]) << state;
    EXPECT_GT(state["passes_compiled"].get<int>(), 0) << state;
}

TEST_F(StudioApiTest, ATypeErrorNamesItsNodeAndPortAndTheLastGoodPackKeepsPlaying) {
    ASSERT_TRUE(compiled(graph("mandelbulb.json"))["ok"]);
    std::string good_revision, revision;
    frame(json::object(), &good_revision);
    auto g = graph("mandelbulb.json");
    g["nodes"][4]["inputs"]["t"] = "bulb.trap";   // palette.cosine's t is a float; trap is a vec4
    auto state = compiled(g);
    EXPECT_FALSE(state["ok"]);
    bool placed = false;
    for (const auto& d : state["diagnostics"])
        placed |= d["pointer"] == "/nodes/4/inputs/t" && d["node"] == "palette" &&
                  d["message"].get<std::string>().find("type mismatch") != std::string::npos;
    EXPECT_TRUE(placed) << state["diagnostics"];
    // The same pack renders (a still preview refines, so its bytes move on).
    frame(json::object(), &revision);
    EXPECT_EQ(revision, good_revision);
}

TEST_F(StudioApiTest, TwoHundredRapidEditsCompileOnlyTheLatestFewAndNeverCrash) {
    auto g = graph("mandelbulb.json");
    auto compiles = session->compiles();
    std::uint64_t last = 0;
    for (int i = 0; i < 200; ++i) {
        g["nodes"][2]["inputs"]["s"] = 0.3 + 0.002 * i;
        last = post("/api/edit", {{"graph", g}}, 202)["revision"].get<std::uint64_t>();
    }
    auto r = client().Get(fmt::format("/api/state?after={}&wait_ms=10000", last).c_str());
    auto state = json::parse(r->body);
    EXPECT_EQ(state["revision"], last);
    EXPECT_TRUE(state["ok"]) << state;
    EXPECT_LT(session->compiles() - compiles, 20u);
    EXPECT_EQ(frame(json::object()).substr(1, 3), "PNG");
}

TEST_F(StudioApiTest, AnUntouchedGraphSavesByteIdenticalAndASavedOneChecks) {
    auto sent = json::parse(client().Get("/api/graph?path=menger.json")->body)["graph"];
    test::as_javascript_writes_it(sent);
    post("/api/save", {{"path", "copy/menger.json"}, {"graph", sent}, {"based_on", "menger.json"}});
    EXPECT_EQ(read(work / "folder/copy/menger.json"), read(work / "folder/menger.json"));
    auto saved = post("/api/save", {{"path", "edited.json"}, {"graph", graph("mandelbulb.json")}});
    EXPECT_TRUE(saved["diagnostics"].empty()) << saved;
}

TEST_F(StudioApiTest, ClickingAPixelProbesTheSurfaceThere) {
    ASSERT_TRUE(compiled(graph("mandelbulb.json"))["ok"]);
    frame(json::object());
    auto hit = post("/api/probe", {{"x", 32}, {"y", 32}});
    ASSERT_TRUE(hit["hit"]) << hit;
    EXPECT_LT(std::abs(hit["distance"].get<double>()), 0.05);
    auto miss = post("/api/probe", {{"x", 0}, {"y", 0}});
    EXPECT_FALSE(miss["hit"]);
}

TEST_F(StudioApiTest, ANodeWithADistanceGetsASmallPreviewOfItsSubgraph) {
    auto r = client().Post("/api/node-preview", json{{"graph", graph("mandelbulb.json")}, {"node", "bulb"}}.dump(),
                           "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->body.substr(1, 3), "PNG");
    r = client().Post("/api/node-preview", json{{"graph", graph("mandelbulb.json")}, {"node", "palette"}}.dump(),
                      "application/json");
    EXPECT_EQ(r->status, 422);
}

}  // namespace fg::studio
