// GMacDSL: the thesis syntax (§4.7-4.8) with the departures listed in the design
// contract (conventional scalar syntax, composite expressions, signature frames,
// normalized classes, comments). Regenerate the parser with tools/antlr/generate.sh.
grammar GMacDsl;

// ---------------------------------------------------------------- file

compilationUnit
    : definition* EOF
    ;

definition
    : frameDefinition
    | transformDefinition
    | subspaceDefinition
    | classDefinition
    | constantDefinition
    | bindingDefinition
    | macroDefinition
    ;

// ---------------------------------------------------------------- frames (Table 4-1)

frameDefinition
    : DEFINE FRAME name AS basisList frameBody END FRAME
    ;

basisList
    : BASIS ':'? '{' name (',' name)* '}'
    ;

frameBody
    : EUCLIDEAN                                              # euclideanFrame
    | SUBSPACE OF name                                       # subspaceFrame
    | ORTHOGONALIZE name                                     # orthogonalizeFrame
    | IPM '=' matrix                                         # ipmFrame
    | TRANSFORM name BY BCM '=' matrix                       # transformedFrame
    | SIGNATURE '(' expr ',' expr (',' expr)? ')'            # signatureFrame
    | SIGNATURE '{' signatureEntry (',' signatureEntry)* '}'  # namedSignatureFrame
    ;

// `e0: 0`: the square of one basis vector, by name.
signatureEntry
    : name ':' expr
    ;

matrix
    : '{' matrixRow (',' matrixRow)* '}'
    ;

matrixRow
    : '{' expr (',' expr)* '}'
    ;

// ---------------------------------------------------------------- transforms (Table 4-2)

transformDefinition
    : DEFINE TRANSFORM name ':' name '->' name AS transformBody END TRANSFORM
    ;

transformBody
    : IDENTITY                                               # identityTransform
    | ALIAS OF name                                          # aliasTransform
    | INVERSE OF name                                        # inverseTransform
    | TRANSPOSE OF name                                      # transposeTransform
    | INVERSE TRANSPOSE OF name                              # inverseTransposeTransform
    | OUTERMORPHISM USING name '.' BCM                       # bcmOutermorphism
    | OUTERMORPHISM USING matrix                             # matrixOutermorphism
    ;

// ---------------------------------------------------------------- subspaces (Table 4-3)

subspaceDefinition
    : DEFINE SUBSPACE qualifiedName AS subspaceBody END SUBSPACE
    ;

subspaceBody
    : BASIS '{' bladeName (',' bladeName)* '}'               # bladeSubspace
    | GA_SPAN '{' name (',' name)* '}'                       # spanSubspace
    ;

// ---------------------------------------------------------------- classes and constants

classDefinition
    : DEFINE NORMALIZED? MULTIVECTOR CLASS qualifiedName AS classItem (';' classItem)* ';'? END MULTIVECTOR CLASS
    ;

classItem
    : NORMALIZED                                             # normalizedItem
    | bladeName ':' expr                                     # constantCoefficientItem
    | qualifiedName                                          # subspaceItem
    ;

constantDefinition
    : DEFINE CONSTANT qualifiedName AS MULTIVECTOR coefficientList END CONSTANT
    ;

coefficientList
    : '{' (coefficient (';' coefficient)* ';'?)? '}'
    ;

coefficient
    : bladeName ':' expr
    ;

// The scalar blade is `1`; other blades join basis vector names with `^`.
bladeName
    : INT
    | name ('^' name)*
    ;

// ---------------------------------------------------------------- class bindings

bindingDefinition
    : DEFINE BINDING name AS USE FRAME name BIND coefficientList limitList* END BINDING
    ;

limitList
    : (MIN | MAX) '{' (limit (';' limit)* ';'?)? '}'
    ;

limit
    : (memberReference | name) ':' expr
    ;

// ---------------------------------------------------------------- macros (§4.7.7, §4.8)

macroDefinition
    : DEFINE MACRO name AS
      INPUTS ':' parameterList
      OUTPUTS ':' parameterList
      PERFORMS ':' statement* END MACRO
    ;

parameterList
    : '{' (parameter (';' parameter)* ';'?)? '}'
    ;

parameter
    : name (':' | AS) qualifiedName
    ;

statement
    : name '=' expr ';'?                                     # assignmentStatement
    | CALL name '{' (callArgument (';' callArgument)* ';'?)? '}' ';'?   # callStatement
    | OUTPUT_BLOCK ';'?                                      # outputStatement
    | JOIN (ON | OFF) ';'?                                   # joinStatement
    | ';'                                                    # emptyStatement
    ;

callArgument
    : name ':' expr
    ;

// ---------------------------------------------------------------- expressions
// One grammar for multivector and scalar expressions; the binder assigns types.
// Precedence, loosest first: + -, the product words, * /, unary minus, ^ (power),
// postfix coefficient access.

expr
    : expr '.' '<' bladeName '>'                             # coefficientExpr
    | <assoc = right> expr '^' expr                          # powerExpr
    | '-' expr                                               # negateExpr
    | '+' expr                                               # plusExpr
    | expr op = ('*' | '/') expr                             # scaleExpr
    | expr op = (GP | OP | SP | LCP | RCP | FDP | HIP | CP | ACP | VEE) expr   # productExpr
    | expr op = ('+' | '-') expr                             # sumExpr
    | '(' expr ')'                                           # parenExpr
    | number                                                 # numberExpr
    | memberReference                                        # memberExpr
    | name '.' MULTIVECTOR coefficientList                   # multivectorExpr
    | qualifiedName '(' (expr (',' expr)*)? ')'              # callExpr
    | qualifiedName '[' expr ']'                             # transformExpr
    | qualifiedName                                          # nameExpr
    ;

// `<x>` or `<ray.origin.x>`: a member of a bound target-language object.
memberReference
    : '<' name ('.' name)* '>'
    ;

number
    : INT
    | FLOAT
    ;

qualifiedName
    : name ('.' name)*
    ;

// Words that are keywords only where the thesis syntax needs them stay usable
// as ordinary names (a function `inverse(...)`, a basis vector named `e`, ...).
name
    : ID
    | INVERSE | TRANSPOSE | IDENTITY | ALIAS | MIN | MAX | ON | OFF | USE | BIND
    | BASIS | SIGNATURE | EUCLIDEAN | ORTHOGONALIZE | USING | BY | OF | BCM | IPM
    | GA_SPAN | NORMALIZED | CALL | JOIN | FRAME | CLASS | BINDING | MACRO
    | CONSTANT | SUBSPACE | TRANSFORM | OUTERMORPHISM | INPUTS | OUTPUTS | PERFORMS
    ;

// ---------------------------------------------------------------- lexer

DEFINE        : 'define';
END           : 'end';
AS            : 'as';
FRAME         : 'frame';
BASIS         : 'basis';
EUCLIDEAN     : 'Euclidean';
SUBSPACE      : 'subspace';
OF            : 'of';
ORTHOGONALIZE : 'orthogonalize';
IPM           : 'IPM';
TRANSFORM     : 'transform';
BY            : 'by';
BCM           : 'BCM';
SIGNATURE     : 'signature';
IDENTITY      : 'identity';
ALIAS         : 'alias';
INVERSE       : 'inverse';
TRANSPOSE     : 'transpose';
OUTERMORPHISM : 'outermorphism';
USING         : 'using';
GA_SPAN       : 'ga_span';
MULTIVECTOR   : 'multivector';
CLASS         : 'class';
NORMALIZED    : 'normalized';
CONSTANT      : 'constant';
BINDING       : 'binding';
USE           : 'use';
BIND          : 'bind';
MIN           : 'min';
MAX           : 'max';
MACRO         : 'macro';
INPUTS        : 'inputs';
OUTPUTS       : 'outputs';
PERFORMS      : 'performs';
CALL          : 'call';
JOIN          : 'join';
ON            : 'on';
OFF           : 'off';

GP  : 'gp';
OP  : 'op';
SP  : 'sp';
LCP : 'lcp';
RCP : 'rcp';
FDP : 'fdp';
HIP : 'hip';
CP  : 'cp';
ACP : 'acp';
VEE : 'vee';

// `output { ... }` carries raw target-language text up to the matching brace.
OUTPUT_BLOCK : 'output' [ \t\r\n]* '{' (~[{}] | NESTED_BRACES)* '}';
fragment NESTED_BRACES : '{' (~[{}] | NESTED_BRACES)* '}';

ARROW     : '->';
LBRACE    : '{';
RBRACE    : '}';
LPAREN    : '(';
RPAREN    : ')';
LBRACKET  : '[';
RBRACKET  : ']';
LT        : '<';
GT        : '>';
COLON     : ':';
SEMI      : ';';
COMMA     : ',';
DOT       : '.';
ASSIGN    : '=';
PLUS      : '+';
MINUS     : '-';
STAR      : '*';
SLASH     : '/';
CARET     : '^';

FLOAT
    : [0-9]+ '.' [0-9]+ EXPONENT?
    | [0-9]+ EXPONENT
    ;
INT : [0-9]+;
fragment EXPONENT : [eE] [+-]? [0-9]+;

ID : [a-zA-Z_] [a-zA-Z_0-9]*;

LINE_COMMENT  : '//' ~[\r\n]* -> channel(HIDDEN);
BLOCK_COMMENT : '/*' .*? '*/' -> channel(HIDDEN);
WS            : [ \t\r\n\f]+ -> channel(HIDDEN);

// Anything else becomes one token the parser reports, instead of a lexer crash.
ERROR_CHAR : .;

