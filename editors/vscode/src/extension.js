// Starts `ecnc lsp` for EdingCNC files and connects VS Code to it over stdio; runs `ecnc debug`
// (the Debug Adapter Protocol over stdio) for launch configurations of type "ecnc".
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration("edingcnc");
  const [command, ...args] = config.get("server.command");
  client = new LanguageClient(
    "edingcnc",
    "EdingCNC language server",
    { command, args },
    {
      documentSelector: [{ scheme: "file", language: "edingcnc" }, { scheme: "untitled", language: "edingcnc" }],
      initializationOptions: { select: config.get("lint.select"), ignore: config.get("lint.ignore") },
      // macro.cnc edited outside VS Code: the server checks the open files beside it again
      synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher("**/*.[cC][nN][cC]") },
    },
  );
  context.subscriptions.push(client);
  context.subscriptions.push(vscode.debug.registerDebugAdapterDescriptorFactory("ecnc", {
    createDebugAdapterDescriptor() {
      const [debugCommand, ...debugArgs] = vscode.workspace.getConfiguration("edingcnc").get("debug.command");
      return new vscode.DebugAdapterExecutable(debugCommand, debugArgs);
    },
  }));
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
