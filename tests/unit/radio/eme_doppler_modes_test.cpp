// WSJT-X's EME Doppler modes: the table of widgets/astro.cpp:192-240 with hand values, then where
// the signals land, from one-way Doppler shifts (the physics each mode promises), and the
// no-TX-QSY period of astro.cpp:242-299.
#include "azt/radio/eme_doppler_modes.hpp"

#include <gtest/gtest.h>

#include "azt/astro/sky.hpp"

namespace azt::radio {
namespace {

TEST(EmeDopplerModes, WsjtxsTableWithHandValues) {
  const EchoDoppler doppler{-400.0, -150.0};  // self echo, DX echo, Hz
  struct Row {
    EmeDopplerMode mode;
    double rx_hz;
    double tx_hz;
  };
  // OnDxEcho's TX in WSJT-X's words: 2·(m_dop − m_dop00/2) − m_dop = 2·(−150 + 200) + 150 = 250.
  for (const Row row :
       {Row{EmeDopplerMode::None, 0.0, 0.0}, Row{EmeDopplerMode::FullDx, -150.0, 150.0},
        Row{EmeDopplerMode::ConstantOnMoon, -200.0, 200.0},
        Row{EmeDopplerMode::OwnEcho, -400.0, 0.0}, Row{EmeDopplerMode::OnDxEcho, -150.0, 250.0},
        Row{EmeDopplerMode::CallDx, 0.0, 400.0}}) {
    const auto c = eme_correction(row.mode, doppler);
    ASSERT_TRUE(c.ok()) << eme_mode_name(row.mode);
    EXPECT_EQ(c->rx_hz, row.rx_hz) << eme_mode_name(row.mode);
    EXPECT_EQ(c->tx_hz, row.tx_hz) << eme_mode_name(row.mode);
    const auto shifted = eme_correction(row.mode, doppler, 1000.0);  // WSJT-X's Tx shift
    EXPECT_EQ(shifted->tx_hz, row.tx_hz + 1000.0);
    EXPECT_EQ(shifted->rx_hz, row.rx_hz);
  }
}

TEST(EmeDopplerModes, WhereTheSignalsLand) {
  // 1296 MHz; the Moon recedes from us at 0.5 km/s and approaches the DX at 0.3 km/s.
  const double f_mhz = 1296.0;
  const double own_one_way = -f_mhz * 1e6 * 0.5 / 299792.458;
  const double dx_one_way = -f_mhz * 1e6 * -0.3 / 299792.458;
  const EchoDoppler doppler{astro::self_echo_doppler_hz(f_mhz, 0.5),
                            astro::dx_echo_doppler_hz(f_mhz, 0.5, -0.3)};
  const double dial = f_mhz * 1e6;
  auto rig = [&](EmeDopplerMode mode) { return *eme_correction(mode, doppler); };
  // FullDx: the DX, listening on the dial, hears our TX shifted by both one-way legs.
  EXPECT_NEAR(dial + rig(EmeDopplerMode::FullDx).tx_hz + own_one_way + dx_one_way, dial, 1e-6);
  // ... and we hear the DX (sending on the dial) where we listen.
  EXPECT_NEAR(dial + dx_one_way + own_one_way, dial + rig(EmeDopplerMode::FullDx).rx_hz, 1e-6);
  // ConstantOnMoon: our signal reaches the Moon on the dial, and we listen on the dial at the Moon.
  EXPECT_NEAR(dial + rig(EmeDopplerMode::ConstantOnMoon).tx_hz + own_one_way, dial, 1e-6);
  EXPECT_NEAR(dial + own_one_way, dial + rig(EmeDopplerMode::ConstantOnMoon).rx_hz, 1e-6);
  // OwnEcho: we send on the dial and hear our echo where we listen.
  EXPECT_NEAR(dial + rig(EmeDopplerMode::OwnEcho).tx_hz + 2.0 * own_one_way,
              dial + rig(EmeDopplerMode::OwnEcho).rx_hz, 1e-6);
  // OnDxEcho: our own echo lands where we hear the DX's echo.
  EXPECT_NEAR(dial + rig(EmeDopplerMode::OnDxEcho).tx_hz + 2.0 * own_one_way,
              dial + rig(EmeDopplerMode::OnDxEcho).rx_hz, 1e-6);
  // CallDx: our echo comes back on the dial.
  EXPECT_NEAR(dial + rig(EmeDopplerMode::CallDx).tx_hz + 2.0 * own_one_way, dial, 1e-6);
}

TEST(EmeDopplerModes, TheDxModesNeedADxLocator) {
  const EchoDoppler self_only{-400.0, std::nullopt};
  EXPECT_FALSE(eme_correction(EmeDopplerMode::FullDx, self_only).ok());
  EXPECT_FALSE(eme_correction(EmeDopplerMode::OnDxEcho, self_only).ok());
  EXPECT_EQ(eme_correction(EmeDopplerMode::FullDx, self_only).error().message,
            "dx Doppler needs the DX station's locator");
  EXPECT_TRUE(eme_correction(EmeDopplerMode::OwnEcho, self_only).ok());
  EXPECT_TRUE(eme_correction(EmeDopplerMode::ConstantOnMoon, self_only).ok());
  EXPECT_TRUE(eme_correction(EmeDopplerMode::CallDx, self_only).ok());
}

TEST(EmeDopplerModes, NamesReadBack) {
  for (const EmeDopplerMode mode :
       {EmeDopplerMode::None, EmeDopplerMode::FullDx, EmeDopplerMode::ConstantOnMoon,
        EmeDopplerMode::OwnEcho, EmeDopplerMode::OnDxEcho, EmeDopplerMode::CallDx}) {
    EXPECT_EQ(parse_eme_mode(eme_mode_name(mode)), mode);
  }
  EXPECT_EQ(parse_eme_mode("self"), EmeDopplerMode::OwnEcho);
  EXPECT_EQ(parse_eme_mode("Self"), std::nullopt);
}

TEST(EmeDopplerModes, TheNoTxQsyInstantIsTheMiddleOfThePeriodHoldingNowPlusTwoSeconds) {
  // 60 s periods. At 100.4 s: 102 s is in the period 60..120, middle 90.
  EXPECT_EQ(next_tx_period(100.4, 60.0).index, 1);
  EXPECT_EQ(next_tx_period(100.4, 60.0).doppler_at_unix_s, 90.0);
  // At 118.9 s: 120 s starts the next period, middle 150.
  EXPECT_EQ(next_tx_period(118.9, 60.0).index, 2);
  EXPECT_EQ(next_tx_period(118.9, 60.0).doppler_at_unix_s, 150.0);
  // 15 s periods at 1000 s: 1002 s is in 990..1005, middle 997.5.
  EXPECT_EQ(next_tx_period(1000.0, 15.0).doppler_at_unix_s, 997.5);
}

TEST(EmeDopplerModes, TheTxCorrectionIsSetOncePerPeriodAndNeverWhileKeyed) {
  TxOncePerPeriod hold;
  const auto first = hold.due(100.0, 60.0, false);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->index, 1);
  hold.written(*first);
  EXPECT_FALSE(hold.due(101.0, 60.0, false));
  EXPECT_FALSE(hold.due(119.0, 60.0, true));  // keyed: the next period waits
  const auto next = hold.due(119.0, 60.0, false);
  ASSERT_TRUE(next);
  EXPECT_EQ(next->index, 2);
  EXPECT_FALSE(hold.due(119.0, 0.0, false));  // no period (WSJT-X's "not applicable")
  hold.forget();
  EXPECT_TRUE(hold.due(101.0, 60.0, false));
}

}  // namespace
}  // namespace azt::radio
