// ConfigStore: the daemon's configuration load/save path (docs/reliability.md R23).
#include "config/config_store.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "azt/linux/file_lock.hpp"
#include "azt/sim/station_sim.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;

const std::string kValid =
    "schema_version = 2\n"
    "[station]\n"
    "grid = \"FN06HE\"\n"
    "alt_m = 300.0\n"
    "[control]\n"
    "window_deg = 0.1\n"
    "[target]\n"
    "name = \"stop\"\n"
    "[[park]]\n"
    "name = \"south\"\n"
    "az_deg = 180.0\n"
    "el_deg = 0.0\n";

class ConfigStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("azt_config_store_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "azeltrack.toml").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  static void write(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
  }
  static std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  /// The UsageError message of ConfigStore::open, or "" if it opened.
  std::string open_error() const {
    try {
      (void)ConfigStore::open(path_);
    } catch (const UsageError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
  std::string path_;
};

TEST_F(ConfigStoreTest, OpensAValidFile) {
  write(path_, kValid);
  const ConfigStore store = ConfigStore::open(path_);
  EXPECT_DOUBLE_EQ(store.config().station.az_control.window_deg, 0.1);
  EXPECT_EQ(store.config().start_target, "stop");
  EXPECT_EQ(store.config().park[0].name, "south");
  EXPECT_TRUE(store.notices().empty());
  EXPECT_EQ(store.get("control.window_deg"), "0.1");
  EXPECT_EQ(store.get("park.1.name"), "\"south\"");
  EXPECT_EQ(store.get("park.2.name"), std::nullopt);
  EXPECT_EQ(store.get("control.nothing"), std::nullopt);
}

TEST_F(ConfigStoreTest, SetSavesValidatedAndKeepsTheOldFileAsBackup) {
  write(path_, kValid);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store.set("control.window_deg", "0.25").ok());
  EXPECT_DOUBLE_EQ(store.config().station.az_control.window_deg, 0.25);
  EXPECT_EQ(read(path_ + ".bak"), kValid);
  const ConfigStore again = ConfigStore::open(path_);
  EXPECT_DOUBLE_EQ(again.config().station.az_control.window_deg, 0.25);
  EXPECT_EQ(again.config().start_target, "stop");  // everything else kept
  ASSERT_TRUE(store.set("park.1.az_deg", "200.5").ok());
  EXPECT_DOUBLE_EQ(ConfigStore::open(path_).config().park[0].position.az_deg, 200.5);
  ASSERT_TRUE(store.set("rotctld.port", "4600").ok());  // a new table is created
  EXPECT_EQ(ConfigStore::open(path_).config().rotctld.port, 4600);
}

TEST_F(ConfigStoreTest, BadChangesAreRefusedAndChangeNothing) {
  write(path_, kValid);
  ConfigStore store = ConfigStore::open(path_);
  struct Case {
    const char* key;
    const char* value;
    const char* error_part;
  };
  for (const Case& c :
       {Case{"control.window_deg", "5.0", "window_deg"},
        Case{"control.window_deg", "nan", "window_deg"},
        Case{"control.window_deg", "\"wide\"", "window_deg"},
        Case{"control.window_deg", "0.1 junk", "not a TOML value"},
        Case{"control.windw_deg", "0.1", "unknown key [control].windw_deg"},
        Case{"station.grid", "\"ZZ99\"", "grid"}, Case{"park.3.az_deg", "10", "no table item 3"},
        Case{"control..x", "1", "empty part"}, Case{"schema_version", "7", "schema_version 7"},
        Case{"station.grid.x", "1", "not a table"}}) {
    const auto r = store.set(c.key, c.value);
    ASSERT_FALSE(r.ok()) << c.key << " = " << c.value;
    EXPECT_NE(r.error().message.find(c.error_part), std::string::npos)
        << c.key << " = " << c.value << ": " << r.error().message;
  }
  EXPECT_EQ(read(path_), kValid);
  EXPECT_FALSE(fs::exists(path_ + ".bak"));
  EXPECT_DOUBLE_EQ(store.config().station.az_control.window_deg, 0.1);
}

TEST_F(ConfigStoreTest, ValidationErrorsNameTheKeyAndLineAndDoNotFallBack) {
  std::string bad = kValid;
  bad.replace(bad.find("window_deg = 0.1"), 16, "window_deg = 9.0");
  write(path_, bad);
  write(path_ + ".bak", kValid);
  const std::string error = open_error();
  EXPECT_NE(error.find("line 6: [control].window_deg"), std::string::npos) << error;
}

TEST_F(ConfigStoreTest, CorruptPrimaryFallsBackToTheBackupLoudly) {
  for (const std::string& corrupt :
       {std::string("[station\ngrid = "), std::string(), std::string(64, '\0'),
        kValid.substr(0, kValid.size() / 2) + "\"\n"}) {
    write(path_, corrupt);
    write(path_ + ".bak", kValid);
    ConfigStore store = ConfigStore::open(path_);
    ASSERT_EQ(store.notices().size(), 1U);
    EXPECT_NE(store.notices()[0].find("using backup"), std::string::npos) << store.notices()[0];
    EXPECT_EQ(store.config().start_target, "stop");
    // The next save sets the corrupt file aside and never rotates it into the backup.
    ASSERT_TRUE(store.set("control.window_deg", "0.3").ok());
    EXPECT_EQ(read(path_ + ".corrupt"), corrupt);
    EXPECT_EQ(read(path_ + ".bak"), kValid);
    EXPECT_DOUBLE_EQ(ConfigStore::open(path_).config().station.az_control.window_deg, 0.3);
    fs::remove(path_ + ".corrupt");
  }
}

TEST_F(ConfigStoreTest, MissingPrimaryRecoversTheBackup) {
  write(path_ + ".bak", kValid);
  const ConfigStore store = ConfigStore::open(path_);
  EXPECT_EQ(store.config().start_target, "stop");
  EXPECT_EQ(store.notices().size(), 1U);
}

TEST_F(ConfigStoreTest, NeitherFileUsableRefusesWithBothReasons) {
  write(path_, "[[[");
  write(path_ + ".bak", "");
  const std::string error = open_error();
  EXPECT_NE(error.find("line 1"), std::string::npos) << error;
  EXPECT_NE(error.find("empty"), std::string::npos) << error;
}

TEST_F(ConfigStoreTest, SchemaZeroIsMigratedAndSavedIdempotently) {
  const std::string v0 =
      "[station]\ngrid = \"FN06HE\"\nheight_m = 250.0\n[target]\nname = \"stop\"\n";
  write(path_, v0);
  ConfigStore store = ConfigStore::open(path_);
  EXPECT_DOUBLE_EQ(store.config().sky.settings.observer.height_m, 250.0);
  ASSERT_EQ(store.notices().size(), 2U);
  EXPECT_NE(store.notices()[0].find("height_m renamed to alt_m"), std::string::npos);
  EXPECT_EQ(read(path_), v0);  // nothing written until a change is saved
  ASSERT_TRUE(store.update([](toml::table&) {}).ok());
  const std::string once = read(path_);
  EXPECT_NE(once.find("schema_version = 2"), std::string::npos) << once;
  EXPECT_NE(once.find("alt_m = 250.0"), std::string::npos) << once;
  EXPECT_EQ(once.find("height_m"), std::string::npos) << once;
  EXPECT_EQ(read(path_ + ".bak"), v0);  // the backup made before the migration is the original
  ASSERT_TRUE(ConfigStore::open(path_).update([](toml::table&) {}).ok());
  EXPECT_EQ(read(path_), once);
  EXPECT_TRUE(ConfigStore::open(path_).notices().empty());
}

TEST_F(ConfigStoreTest, SchemaZeroWithBothHeightsIsRefused) {
  write(path_, "[station]\ngrid = \"FN06HE\"\nheight_m = 1.0\nalt_m = 2.0\n");
  EXPECT_NE(open_error().find("both height_m"), std::string::npos) << open_error();
}

TEST_F(ConfigStoreTest, FutureSchemaIsRefused) {
  write(path_, "schema_version = 3\n");
  EXPECT_NE(open_error().find("schema_version 3 is not supported"), std::string::npos);
  write(path_, "schema_version = \"1\"\n");
  EXPECT_NE(open_error().find("schema_version must be"), std::string::npos);
}

TEST_F(ConfigStoreTest, CorrectionsAndTheTiltTableAreSettings) {
  std::string tilt = "[";
  for (int i = 0; i < 60; ++i) tilt += (i > 0 ? ", " : "") + std::to_string(i % 5 * 0.1);
  tilt += "]";
  write(path_, kValid + "[corrections]\naz_offset_deg = -3.4\nel_user_deg = 0.25\ntilt_el_deg = " +
                   tilt + "\n");
  ConfigStore store = ConfigStore::open(path_);
  const auto& c = store.config().station.corrections;
  EXPECT_DOUBLE_EQ(c.offsets.az_deg, -3.4);
  EXPECT_EQ(c.user.el_steps(), 25);
  EXPECT_DOUBLE_EQ(c.tilt.entries_deg()[7], 0.2);
  const std::string sixty_one = tilt.substr(0, tilt.size() - 1) + ", 0.5]";
  EXPECT_FALSE(store.set("corrections.tilt_el_deg", sixty_one).ok());
  // one entry edited, as the tilt-table screen does, survives a reload
  ASSERT_TRUE(store
                  .update([](toml::table& root) {
                    (*root["corrections"]["tilt_el_deg"].as_array())
                        .replace(root["corrections"]["tilt_el_deg"].as_array()->begin() + 3, 1.25);
                  })
                  .ok());
  EXPECT_DOUBLE_EQ(ConfigStore::open(path_).config().station.corrections.tilt.entries_deg()[3],
                   1.25);
  for (const char* bad : {"[1.0, 2.0]", "6.0"}) {
    const auto r = store.set("corrections.tilt_el_deg", bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.error().message.find("tilt_el_deg"), std::string::npos) << r.error().message;
  }
  const auto r = store.set("corrections.el_user_deg", "12.0");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("el_user_deg"), std::string::npos) << r.error().message;
}

const std::string kCommented =
    "# my station, do not lose these notes\n"
    "schema_version = 2\n"
    "\n"
    "[station]\n"
    "grid = \"FN06HE\"   # the home QTH\n"
    "alt_m = 300.0\n"
    "\n"
    "[control]\n"
    "window_deg = 0.1   # the seed's movement window\n"
    "ramp_s = 1.0\n"
    "\n"
    "[[park]]           # slot 1\n"
    "name = \"south\"\n"
    "az_deg = 180.0\n"
    "el_deg = 0.0\n"
    "\n"
    "[target]\n"
    "name = \"stop\"    # start stopped\n";

TEST_F(ConfigStoreTest, SavesKeepCommentsAndChangeOnlyTheValue) {
  write(path_, kCommented);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store.set("control.window_deg", "0.25").ok());
  std::string expected = kCommented;
  expected.replace(expected.find("window_deg = 0.1 "), 17, "window_deg = 0.25 ");
  EXPECT_EQ(read(path_), expected);
  ASSERT_TRUE(store.set("park.1.az_deg", "200.5").ok());
  expected.replace(expected.find("az_deg = 180.0"), 14, "az_deg = 200.5");
  EXPECT_EQ(read(path_), expected);
}

TEST_F(ConfigStoreTest, NewKeysAndTablesGetLinesOfTheirOwn) {
  write(path_, kCommented);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store.set("control.tracking_speed", "0.4").ok());
  ASSERT_TRUE(store.set("web.port", "8090").ok());
  const std::string text = read(path_);
  EXPECT_NE(text.find("ramp_s = 1.0\ntracking_speed = 0.4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n[web]\nport = 8090\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# my station, do not lose these notes"), std::string::npos);
  EXPECT_NE(text.find("# start stopped"), std::string::npos);
  EXPECT_EQ(ConfigStore::open(path_).config().web.port, 8090);
}

TEST_F(ConfigStoreTest, NewSubTablesAndItemsKeepTheComments) {
  // The console's settings add tables at any depth and items after the others.
  write(path_, kCommented);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store
                  .update([](toml::table& root) {
                    root.insert("mount", toml::table{{"az", toml::table{{"encoder_bits", 14}}}});
                    root["park"].as_array()->push_back(toml::table{{"name", "stow"}});
                  })
                  .ok());
  ASSERT_TRUE(store.set("mount.el.max_rate_deg_s", "2.0").ok());
  const std::string text = read(path_);
  EXPECT_NE(text.find("\n[mount.az]\nencoder_bits = 14\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n[[park]]\nname = \"stow\"\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n[mount.el]\nmax_rate_deg_s = 2.0\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("\n[mount]\n"), std::string::npos) << "no header of its own: " << text;
  EXPECT_NE(text.find("# my station, do not lose these notes"), std::string::npos) << text;
  EXPECT_NE(text.find("[[park]]           # slot 1"), std::string::npos) << text;
  const DaemonConfig c = ConfigStore::open(path_).config();
  EXPECT_EQ(c.mount.az.encoder_bits, 14);
  EXPECT_DOUBLE_EQ(c.mount.el.max_rate_deg_s, 2.0);
  EXPECT_EQ(c.park[1].name, "stow");
  EXPECT_EQ(c.park[0].name, "south");
}

TEST_F(ConfigStoreTest, RemovedKeysLoseTheirLine) {
  write(path_, kCommented);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store
                  .update([](toml::table& root) {
                    toml::table& s = *root["station"].as_table();
                    s.erase("grid");
                    s.insert_or_assign("lat_deg", 52.0);
                    s.insert_or_assign("lon_deg", 5.0);
                  })
                  .ok());
  const std::string text = read(path_);
  EXPECT_EQ(text.find("FN06HE"), std::string::npos) << text;
  EXPECT_NE(text.find("alt_m = 300.0\nlat_deg = 52.0\nlon_deg = 5.0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("# the seed's movement window"), std::string::npos);
  EXPECT_DOUBLE_EQ(ConfigStore::open(path_).config().sky.settings.observer.lat_deg, 52.0);
}

TEST_F(ConfigStoreTest, StartTargetsAreFoundByNameOrAlias) {
  write(path_, kValid);
  ConfigStore store = ConfigStore::open(path_);
  for (const char* name :
       {"\"moon\"", "\"Sun\"", "\"Cassiopeia A\"", "\"cassiopeiaa\"", "\"stop\""}) {
    EXPECT_TRUE(store.set("target.name", name).ok()) << name;
  }
}

TEST_F(ConfigStoreTest, TwoWritersNeverLoseEachOthersChanges) {
  write(path_, kValid);
  ConfigStore a = ConfigStore::open(path_);
  ConfigStore b = ConfigStore::open(path_);
  ASSERT_TRUE(a.set("control.window_deg", "0.4").ok());
  ASSERT_TRUE(b.set("target.name", "\"sun\"").ok());  // b loaded before a saved
  const ConfigStore now = ConfigStore::open(path_);
  EXPECT_DOUBLE_EQ(now.config().station.az_control.window_deg, 0.4);
  EXPECT_EQ(now.config().start_target, "sun");
}

TEST_F(ConfigStoreTest, TheShippedDefaultSurvivesASaveUnchangedInMeaning) {
  write(path_, default_config_text());
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store.update([](toml::table&) {}).ok());
  const std::string saved = read(path_);
  // Serializing what was saved gives the same bytes: save -> load -> save is the identity.
  const ConfigStore reopened = ConfigStore::open(path_);
  ASSERT_TRUE(ConfigStore::open(path_).update([](toml::table&) {}).ok());
  EXPECT_EQ(read(path_), saved);
  EXPECT_EQ(reopened.config().serial.size(), store.config().serial.size());
  EXPECT_EQ(reopened.config().park[1].name, store.config().park[1].name);
  EXPECT_EQ(reopened.config().rotctld.port, 4533);
}

// docs/reliability.md "Hardening" row 7: two saves, a corrupt file, a third save. The third must
// build on the second (this process wrote it), never on the older .bak.
TEST_F(ConfigStoreTest, ACorruptFileIsRebuiltFromTheLastSaveNotFromTheOlderBackup) {
  write(path_, kValid);
  ConfigStore store = ConfigStore::open(path_);
  ASSERT_TRUE(store.set("control.window_deg", "0.2").ok());
  ASSERT_TRUE(store.set("control.window_deg", "0.3").ok());  // .bak now holds 0.2
  write(path_, "\xff\xfe garbage [[[");
  ASSERT_TRUE(store.set("target.name", "\"sun\"").ok());
  const ConfigStore again = ConfigStore::open(path_);
  EXPECT_DOUBLE_EQ(again.config().station.az_control.window_deg, 0.3);
  EXPECT_EQ(again.config().start_target, "sun");
  EXPECT_EQ(read(path_ + ".corrupt"), "\xff\xfe garbage [[[");
  ASSERT_FALSE(store.notices().empty());
  EXPECT_NE(store.notices().back().find("set aside"), std::string::npos) << store.notices().back();
}

TEST_F(ConfigStoreTest, ACorruptFileThatHeldAnotherProgramsSaveIsNotRebuilt) {
  write(path_, kValid);
  ConfigStore daemon = ConfigStore::open(path_);
  ASSERT_TRUE(daemon.set("control.window_deg", "0.2").ok());
  ConfigStore cli = ConfigStore::open(path_);
  ASSERT_TRUE(cli.set("target.name", "\"moon\"").ok());  // .bak is now the daemon's version
  write(path_, "");
  const auto saved = daemon.set("control.window_deg", "0.5");
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().message.find("another program saved it"), std::string::npos)
      << saved.error().message;
  EXPECT_EQ(read(path_), "");  // nothing written: the operator decides
  EXPECT_FALSE(fs::exists(path_ + ".corrupt"));
}

// docs/reliability.md "Hardening" row 3: a lock held elsewhere makes the save wait a bounded time,
// then fail clearly.
TEST_F(ConfigStoreTest, AHeldLockFailsTheSaveAfterTheWaitAndChangesNothing) {
  write(path_, kValid);
  const ConfigStore store = ConfigStore::open(path_);
  auto held = linux_os::FileLock::acquire(path_ + ".lock", 0.0);  // another open file: conflicts
  ASSERT_TRUE(held.ok());
  ConfigStore::SaveBase base = store.save_base();
  base.lock_wait_s = 0.1;
  const auto saved = ConfigStore::save_change(base, [](toml::table& root) {
    root.insert_or_assign("log", toml::table{{"level", "warn"}});
  });
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().message.find("held by another program"), std::string::npos)
      << saved.error().message;
  EXPECT_EQ(read(path_), kValid);
}

// docs/reliability.md "Hardening" row 11: temps of killed writers go at open; what is created is
// private.
TEST_F(ConfigStoreTest, TempFilesOfDeadWritersGoAtStartAndNewFilesArePrivate) {
  write(path_, kValid);
  pid_t dead = 4194303;  // above the usual pid_max; checked below
  while (::kill(dead, 0) == 0 || errno == EPERM) --dead;
  write(path_ + ".tmp." + std::to_string(dead), kValid);
  write(path_ + ".bak.tmp." + std::to_string(dead), kValid);
  write(path_ + ".tmp.1", kValid);  // pid 1 is alive: its writer may still finish
  ConfigStore store = ConfigStore::open(path_);
  EXPECT_TRUE(fs::exists(path_ + ".tmp." + std::to_string(dead)));  // open only reads
  const auto notice = store.remove_stale_temps();
  ASSERT_TRUE(notice.has_value());
  EXPECT_NE(notice->find("removed 2 temp file(s)"), std::string::npos) << *notice;
  EXPECT_FALSE(fs::exists(path_ + ".tmp." + std::to_string(dead)));
  EXPECT_FALSE(fs::exists(path_ + ".bak.tmp." + std::to_string(dead)));
  EXPECT_TRUE(fs::exists(path_ + ".tmp.1"));
  ASSERT_TRUE(store.set("control.window_deg", "0.2").ok());
  const auto mode = fs::status(path_ + ".lock").permissions();
  EXPECT_EQ(mode & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
}

// A schema-1 file set the real mount's speed and encoders under [sim.az]. It loads
// into the same controller setup as the same mount written in schema 2's [mount.az], and the
// simulated plant keeps its imperfections.
TEST_F(ConfigStoreTest, SchemaOneSimRatesBecomeTheMountsWithTheSameControllerSetup) {
  const std::string v1 =
      "schema_version = 1\n[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n"
      "[sim.az]\nmax_rate_deg_s = 3.0\nencoder_bits = 14\ntime_constant_s = 0.5\n"
      "stiction_duty = 0.2\nbacklash_deg = 0.1\nstart_deg = 90.0\n"
      "[sim.el]\nmax_rate_deg_s = 0.8\nencoder_bits = 10\n";
  const std::string v2 =
      "schema_version = 2\n[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n"
      "[mount.az]\nmax_rate_deg_s = 3.0\nencoder_bits = 14\ntime_constant_s = 0.5\n"
      "min_duty = 0.2\nbacklash_deg = 0.1\n[mount.el]\nmax_rate_deg_s = 0.8\n"
      "encoder_bits = 10\n[sim.az]\nstart_deg = 90.0\n";
  write(path_, v1);
  ConfigStore old = ConfigStore::open(path_);
  const std::string v2_path = (dir_ / "v2.toml").string();
  write(v2_path, v2);
  ConfigStore now = ConfigStore::open(v2_path);
  const auto a = sim::station_control_config(old.config().simulated());
  const auto b = sim::station_control_config(now.config().simulated());
  EXPECT_DOUBLE_EQ(a.az_control.max_rate_deg_s, 3.0);
  EXPECT_DOUBLE_EQ(a.az_control.lsb_deg, 360.0 / 16384.0);
  EXPECT_DOUBLE_EQ(a.el_control.lsb_deg, 360.0 / 1024.0);
  EXPECT_DOUBLE_EQ(a.az_control.time_constant_s, 0.5);
  EXPECT_DOUBLE_EQ(a.az_control.min_duty, 0.2);
  EXPECT_DOUBLE_EQ(a.az_control.backlash_deg, 0.1);
  for (const auto& [x, y] :
       {std::pair{&a.az_control, &b.az_control}, std::pair{&a.el_control, &b.el_control}}) {
    EXPECT_DOUBLE_EQ(x->max_rate_deg_s, y->max_rate_deg_s);
    EXPECT_DOUBLE_EQ(x->lsb_deg, y->lsb_deg);
    EXPECT_DOUBLE_EQ(x->time_constant_s, y->time_constant_s);
    EXPECT_DOUBLE_EQ(x->min_duty, y->min_duty);
    EXPECT_DOUBLE_EQ(x->backlash_deg, y->backlash_deg);
  }
  EXPECT_DOUBLE_EQ(a.az_supervisor.max_rate_deg_s, b.az_supervisor.max_rate_deg_s);
  EXPECT_DOUBLE_EQ(a.el_supervisor.lsb_deg, b.el_supervisor.lsb_deg);
  // The simulated plant is the same too: the mount's rate and bits, its own imperfections.
  const auto& plant = old.config().sim.az;
  EXPECT_DOUBLE_EQ(plant.max_rate_deg_s, 3.0);
  EXPECT_EQ(plant.encoder_bits, 14);
  EXPECT_DOUBLE_EQ(plant.stiction_duty, 0.2);
  EXPECT_DOUBLE_EQ(plant.start_deg, 90.0);
  // Saved once: [mount.*] in the file, the original in .bak, and a second load changes nothing.
  ASSERT_TRUE(old.update([](toml::table&) {}).ok());
  EXPECT_EQ(read(path_ + ".bak"), v1);
  const std::string saved = read(path_);
  EXPECT_NE(saved.find("[mount.az]"), std::string::npos) << saved;
  EXPECT_EQ(saved.find("encoder_bits", saved.find("[sim.az]")), std::string::npos) << saved;
  EXPECT_TRUE(ConfigStore::open(path_).notices().empty());
}

TEST_F(ConfigStoreTest, AMountRateInTheSimulatorsTableIsRefusedInSchemaTwo) {
  write(path_,
        "schema_version = 2\n[station]\ngrid = \"FN06HE\"\n[sim.az]\nmax_rate_deg_s = 3.0\n");
  EXPECT_NE(open_error().find("max_rate_deg_s"), std::string::npos) << open_error();
}

}  // namespace
}  // namespace azt::app
