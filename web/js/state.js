// The console's one state object: what the controller last said, and what the page is doing.

export const S = {
  state: null, config: null, targets: null, sky: null, screen: 'main',
  loggedIn: false, csrf: null, passwordSet: true,
  loginDismissed: localStorage.getItem('azt.loginbar') === 'hidden',
  sel: null, // what TRACK starts: {body, label, serverName}
  ws: null, connected: false, backoff: 250, attempts: 0, lastMsg: 0, openedAt: 0, retryTimer: 0,
  trend: [], trendDrawn: 0, skyDrawn: 0, skyListDrawn: 0, faultsKey: '', eventsKey: '', commandsKey: '', ioKey: '', dopKey: '',
};
